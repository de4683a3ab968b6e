// Fuzzes the topological map GraphML reader (libs/rooms TopologicalMapIO.h, public API only).
#include <toposlam/rooms/TopologicalMapIO.h>

#include "FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    toposlam::fuzz::expectOnlyInputErrors(
        "rooms_graphml", [&] { toposlam::rooms::topologicalMapFromGraphML(text, "fuzz.graphml"); });
    return 0;
}
