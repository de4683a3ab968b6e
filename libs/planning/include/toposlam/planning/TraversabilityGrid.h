#pragma once
// Where a disc-shaped robot can stand on an occupancy grid: a cell is traversable when it is
// free and the robot, centred on the cell, touches no cell that is occupied or unknown.
// Computed once per map with a Euclidean distance transform, so queries are O(1).
// World frame and metres of the source grid; images follow rooms::GridImageFrame (row 0 =
// largest y), so they line up with a TopologicalMap built from the same grid.
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPoint2D.h>
#include <toposlam/rooms/GridImageFrame.h>

#include <opencv2/core/mat.hpp>
#include <optional>

namespace toposlam::planning {

class TraversabilityGrid {
  public:
    /// `robotRadius` (m): clearance needed around the robot's centre. `freeThreshold`: cells
    /// with p(free) above it are free; everything else (occupied, unknown) is an obstacle.
    TraversabilityGrid(const mrpt::maps::COccupancyGridMap2D& grid, double robotRadius,
                       double freeThreshold = 0.6);

    const rooms::GridImageFrame& frame() const { return frame_; }
    double robotRadius() const { return robotRadius_; }

    /// Whether the robot can stand at world point (x, y) (m). False outside the map.
    bool isTraversable(double x, double y) const {
        const cv::Point c = frame_.toCell(x, y);
        return frame_.contains(c) && traversable_.at<std::uint8_t>(c) != 0;
    }
    bool isTraversableCell(const cv::Point& cell) const {
        return frame_.contains(cell) && traversable_.at<std::uint8_t>(cell) != 0;
    }
    /// Whether the robot can move straight from a to b (world, m): every point of the segment,
    /// sampled at a quarter cell, is traversable. Stops at the first blocked sample.
    bool isSegmentTraversable(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b) const;
    /// Distance (m) from the centre of the cell holding (x, y) to the nearest obstacle's
    /// boundary; 0 outside the map and on obstacles.
    double clearance(double x, double y) const;

    /// CV_8U, 255 = traversable.
    const cv::Mat& traversable() const { return traversable_; }

    /// The traversable cell centre nearest to `p` within `maxDistance` (m), if any.
    std::optional<mrpt::math::TPoint2D> nearestTraversable(const mrpt::math::TPoint2D& p,
                                                           double maxDistance) const;

  private:
    rooms::GridImageFrame frame_;
    double robotRadius_;
    cv::Mat traversable_;  ///< CV_8U
    cv::Mat clearanceM_;   ///< CV_32F, metres
};

}  // namespace toposlam::planning
