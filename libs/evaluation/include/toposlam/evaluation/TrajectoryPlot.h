#pragma once
// A picture of several trajectories on one map-like plot (PNG), for a look at what the numbers
// of an evaluation mean: where a method drifts, where a corridor got bent.
#include <mrpt/math/TPose2D.h>
#include <toposlam/io/Trajectory.h>

#include <string>
#include <vector>

namespace toposlam::evaluation {

struct PlottedTrajectory {
    std::string label;  ///< legend text
    io::Trajectory2D poses;
};

/// The rigid 2D transform (trajectory frame -> reference frame) that best aligns the positions
/// of `trajectory` with those of `reference` at the same stamps (within `stampTolerance`, s);
/// the identity when they have fewer than 2 stamps in common.
mrpt::math::TPose2D alignmentTo(const io::Trajectory2D& reference,
                                const io::Trajectory2D& trajectory, double stampTolerance);

/// Moves each trajectory by the rigid 2D transform that best aligns its positions with those of
/// `reference` at the same stamps (within `stampTolerance`, s), so that all are drawn in the
/// reference's frame. Trajectories with fewer than 2 poses in common are left as they are.
std::vector<PlottedTrajectory> alignedTo(const io::Trajectory2D& reference,
                                         std::vector<PlottedTrajectory> trajectories,
                                         double stampTolerance);

/// Draws the trajectories (x right, y up, equal scale, a metric grid, a legend) into a PNG of
/// `widthPixels` width, written atomically to `path`. Throws std::runtime_error when the file
/// cannot be written, std::invalid_argument when there is nothing to draw.
void saveTrajectoryPlot(const std::vector<PlottedTrajectory>& trajectories, const std::string& path,
                        int widthPixels = 1200);

}  // namespace toposlam::evaluation
