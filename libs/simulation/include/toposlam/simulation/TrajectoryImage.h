#pragma once
// A picture of a trajectory over its map, for users who would rather look than read: the map in
// grey (black occupied, white free, grey unknown), the path in red with a green start, and
// optional marked places (e.g. the room-sized areas a tour visits) as blue circles.
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPoint2D.h>
#include <toposlam/io/Trajectory.h>

#include <string>
#include <vector>

namespace toposlam::simulation {

/// Writes a PNG (atomically), `scale` pixels per map cell, north up.
void saveTrajectoryImage(const mrpt::maps::COccupancyGridMap2D& map,
                         const io::Trajectory2D& trajectory,
                         const std::vector<mrpt::math::TPoint2D>& marks, const std::string& path,
                         int scale = 2);

}  // namespace toposlam::simulation
