#pragma once
// How a long-running library function reports progress: it calls the callback with the
// fraction done and the number of items (scans, maps, pairs) processed so far. Libraries never
// draw anything themselves; apps pass a callback that feeds io::ProgressDisplay (or nothing).
#include <cstddef>
#include <functional>

namespace toposlam::io {

/// `fraction` in [0, 1], `itemsDone` since the start. Called often; keep it cheap.
using ProgressCallback = std::function<void(double fraction, std::size_t itemsDone)>;

}  // namespace toposlam::io
