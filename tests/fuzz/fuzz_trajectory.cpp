// Fuzzes the trajectory reader (libs/io Trajectory.h: "timestamp x y yaw" lines).
#include <toposlam/io/Trajectory.h>

#include "FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string path = toposlam::fuzz::writeScratchFile(
        "fuzz.txt", std::string_view(reinterpret_cast<const char*>(data), size));
    toposlam::fuzz::expectOnlyInputErrors("trajectory",
                                          [&] { toposlam::io::loadTrajectory(path); });
    return 0;
}
