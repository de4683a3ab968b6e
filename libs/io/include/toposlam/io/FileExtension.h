#pragma once
// File names carry their format ("map.gridmap.gz", "plan.PNG"): one test for every reader and
// writer that picks a format by name, so they agree on what a name means.
#include <initializer_list>
#include <string_view>

namespace toposlam::io {

/// True if `path` ends with `extension` (given with its dot, e.g. ".gridmap.gz") and something
/// comes before it. ASCII case is ignored: "MAP.PNG" is a PNG.
bool hasExtension(std::string_view path, std::string_view extension);

/// True if `path` has one of `extensions` (see hasExtension).
bool hasAnyExtension(std::string_view path, std::initializer_list<std::string_view> extensions);

}  // namespace toposlam::io
