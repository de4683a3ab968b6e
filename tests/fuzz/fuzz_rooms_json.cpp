// Fuzzes the topological map JSON reader (libs/rooms TopologicalMapIO.h, public API only).
#include <toposlam/rooms/TopologicalMapIO.h>

#include "FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    toposlam::fuzz::expectOnlyInputErrors(
        "rooms_json", [&] { toposlam::rooms::topologicalMapFromJson(text, "fuzz.json"); });
    return 0;
}
