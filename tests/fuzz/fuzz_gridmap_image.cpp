// Fuzzes image grid maps with their sidecar (libs/io loadGridMap on "map.png" beside
// "map.yaml"; the image is also "map.pgm", so that a YAML naming the ROS pair written with a
// picture is exercised too). Input: the YAML, a NUL byte, the image file.
#include <toposlam/io/GridMapIO.h>

#include "FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto [yaml, image] = toposlam::fuzz::splitAtNul(data, size);
    toposlam::fuzz::writeScratchFile("map.yaml", yaml);
    toposlam::fuzz::writeScratchFile("map.pgm", image);
    const std::string path = toposlam::fuzz::writeScratchFile("map.png", image);
    toposlam::fuzz::expectOnlyInputErrors("gridmap_image",
                                          [&] { toposlam::io::loadGridMap(path); });
    return 0;
}
