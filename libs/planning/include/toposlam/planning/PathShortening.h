#pragma once
// Pulls a collision-free polyline taut: from each kept point, jump to the farthest later point
// that is in straight line of sight (TraversabilityGrid::isSegmentTraversable). The path is
// first resampled every `spacing` metres so corners can also be cut between original
// vertices. Deterministic, never longer than its input, and it keeps the path collision-free.
// Sampling planners (RRT-Connect) return wandering paths whose random shortcutting leaves
// detours; this removes them.
#include <mrpt/math/TPoint2D.h>
#include <toposlam/planning/TraversabilityGrid.h>

#include <vector>

namespace toposlam::planning {

/// `path` must be collision-free on `grid`; `spacing` in m (> 0).
std::vector<mrpt::math::TPoint2D> shortenPath(const TraversabilityGrid& grid,
                                              const std::vector<mrpt::math::TPoint2D>& path,
                                              double spacing = 0.25);

}  // namespace toposlam::planning
