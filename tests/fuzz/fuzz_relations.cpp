// Fuzzes the ground-truth relations reader (libs/evaluation RelationFile.h).
#include <toposlam/evaluation/RelationFile.h>

#include "FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string path = toposlam::fuzz::writeScratchFile(
        "fuzz.relations", std::string_view(reinterpret_cast<const char*>(data), size));
    toposlam::fuzz::expectOnlyInputErrors("relations",
                                          [&] { toposlam::evaluation::loadRelations(path); });
    return 0;
}
