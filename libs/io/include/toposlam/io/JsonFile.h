#pragma once
// JSON files in and out, with nlohmann::json (Debian's nlohmann-json3-dev) for every JSON
// TopoSLAM reads or writes. Reading refuses nesting deeper than kMaxJsonDepth (no TopoSLAM
// document comes near it; a hostile file cannot exhaust the stack of code that walks the tree)
// and reports problems as io::InputError naming the file, line and column. Writing is atomic.
#include <nlohmann/json.hpp>

#include <string>

namespace toposlam::io {

/// Objects keep their keys in insertion order, so written files read in a sensible order.
using Json = nlohmann::ordered_json;

constexpr int kMaxJsonDepth = 64;

/// Parses `text`; throws InputError(sourceName, "JSON syntax error at line L, column C: ...")
/// or InputError(sourceName, "JSON nested deeper than 64 levels").
Json parseJson(const std::string& text, const std::string& sourceName);

/// Reads and parses the file at `path` (InputError when it cannot be read or parsed).
Json loadJsonFile(const std::string& path);

/// `document` with two-space indentation and a final newline; NaN and infinities as null.
std::string formatJson(const Json& document);

/// `v` rounded to `digits` significant digits / `decimals` decimals, so that JSON shows 0.05
/// and not 0.05000000074505806 (a float widened) or 0.12345678912 (more than is meaningful).
/// Non-finite values pass through (and are written as null).
double roundSignificant(double v, int digits);
double roundDecimals(double v, int decimals);

/// Writes formatJson(document) to `path` atomically (AtomicFile.h); throws std::runtime_error
/// naming `path` when it cannot be written.
void saveJsonFile(const Json& document, const std::string& path);

}  // namespace toposlam::io
