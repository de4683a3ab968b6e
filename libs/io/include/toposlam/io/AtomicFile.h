#pragma once
// Writing output files so that a failure never leaves a partial or corrupted file behind:
// the content goes to a temporary file in the destination's directory, which is renamed
// over the destination only after the writer returned successfully.
#include <functional>
#include <string>

namespace toposlam::io {

/// Calls `writeTo(tmpPath)`, then renames tmpPath to `path`. If `writeTo` throws, or the
/// rename fails, the temporary file is removed and the exception propagates (rename failure:
/// std::runtime_error naming `path`). The temporary name keeps the destination's extension
/// (e.g. "map.tmp123.gridmap.gz"), so writers that pick a format by extension still work.
void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tmpPath)>& writeTo);

}  // namespace toposlam::io
