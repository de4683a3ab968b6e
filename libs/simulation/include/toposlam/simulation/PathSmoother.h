#pragma once
// Turns the staircase of an 8-connected grid path into the smooth curve a robot drives:
// resample by arc length, convolve with a Gaussian (the ends are extended by point reflection, so
// they stay put and keep their direction), and never move a point to where the robot would lack
// clearance: such points are pulled back towards the original path until they are valid again.
#include <mrpt/math/TPoint2D.h>
#include <toposlam/simulation/GridPathPlanner.h>

#include <vector>

namespace toposlam::simulation {

/// Points of `path` (world frame, m) every `spacing` metres of arc length, keeping both ends.
std::vector<mrpt::math::TPoint2D> resamplePolyline(const std::vector<mrpt::math::TPoint2D>& path,
                                                   double spacing);

/// The smoothed path, sampled every `spacing` m. `sigma` (m) is the Gaussian's standard deviation
/// along the path: corners get rounded over about 2*sigma. When every input point is traversable
/// for `planner`, so is every smoothed point; the returned points are resampled from those, so
/// each lies within `spacing` of two traversable points (the planner's clearance keeps a margin
/// for that: use a spacing below the grid resolution).
std::vector<mrpt::math::TPoint2D> smoothPath(const std::vector<mrpt::math::TPoint2D>& path,
                                             const GridPathPlanner& planner, double sigma,
                                             double spacing);

}  // namespace toposlam::simulation
