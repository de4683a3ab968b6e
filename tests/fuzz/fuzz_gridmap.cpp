// Fuzzes the .gridmap reader (libs/io loadGridMap: MRPT-serialized COccupancyGridMap2D).
// Input: one flag byte ('1': the rest is gzip-compressed, as .gridmap.gz) + the file.
#include <toposlam/io/GridMapIO.h>

#include "FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1)
        return 0;
    const std::string_view file(reinterpret_cast<const char*>(data + 1), size - 1);
    const std::string path = toposlam::fuzz::writeScratchFile("map.gridmap", file, data[0] == '1');
    toposlam::fuzz::expectOnlyInputErrors("gridmap", [&] { toposlam::io::loadGridMap(path); });
    return 0;
}
