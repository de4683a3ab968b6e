// Fuzzes ROS map_server maps (libs/io loadGridMap on "ros.yaml" and the "ros.pgm" it names).
// Input: the YAML, a NUL byte, the image file.
#include <toposlam/io/GridMapIO.h>

#include "FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto [yaml, image] = toposlam::fuzz::splitAtNul(data, size);
    toposlam::fuzz::writeScratchFile("ros.pgm", image);
    const std::string path = toposlam::fuzz::writeScratchFile("ros.yaml", yaml);
    toposlam::fuzz::expectOnlyInputErrors("ros_map", [&] { toposlam::io::loadGridMap(path); });
    return 0;
}
