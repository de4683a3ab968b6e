#pragma once
// Where step 4 of the virtual-door method starts its door search. The paper searches from the
// free cells of the robot's mapping trajectory: assumption (2), the robot went through every
// door while it built the map.
//
// Maps without a trajectory (the public benchmark maps) need a substitute with the same
// property. TopoSLAM uses the medial axis of the free space: every passage between two parts of
// the free space, doors included, is crossed by it, because the medial axis has the topology of
// the free space. It is computed as the ridge of the Euclidean distance transform: cells whose
// clearance is a local maximum across at least one of the four grid axes. Of the ridge only
// the cells whose clearance is that of a door's middle are kept, between half the smallest and
// half the largest door width (one cell of slack each way for discretisation): a wider ridge
// cell cannot lie between two jambs at door distance, a narrower one lies on a spur towards a
// corner or along a wall.
#include <toposlam/rooms/FreeSpaceBinarizer.h>

#include <mrpt/math/TPose2D.h>

#include <opencv2/core/mat.hpp>

#include <utility>
#include <vector>

namespace toposlam::rooms {

/// Clearance of the free space: for every cell the Euclidean distance (pixels, 5x5-mask
/// distance transform: cv::distanceTransform's DIST_L2 / DIST_MASK_5 values, computed in half
/// its time) to the nearest non-free cell. compute() reuses its image.
class Clearance {
  public:
    Clearance() = default;
    explicit Clearance(const cv::Mat& free) { compute(free); }
    /// `free`: CV_8U, non-zero = free.
    void compute(const cv::Mat& free);

    /// pixels; 0 on non-free cells
    float distance(const cv::Point& p) const { return distance_.at<float>(p); }
    const cv::Mat& distances() const { return distance_; }
    /// Direction (image radians, [0, pi)) across the ridge of the clearance at `p`: the
    /// direction of strongest negative curvature (Hessian over +-2 cells). On the medial axis of
    /// a doorway the clearance peaks between the jambs, so this is the door line, whatever the
    /// orientation of the wall.
    double acrossRidge(const cv::Point& p) const;
    /// acrossRidge() of each cell, in order: the local door directions of a search path.
    std::vector<double> acrossRidge(const std::vector<cv::Point>& cells) const;

  private:
    cv::Mat distance_;
    std::vector<int> rows_;  // compute()'s scratch
};

class DoorSearchPaths {
  public:
    /// Cells of the polyline through `poses` (world frame of space.frame, m) that are free in
    /// space.free, each once, in path order. Consecutive poses are joined by a straight line:
    /// the robot crossed those cells between them.
    static std::vector<cv::Point> fromTrajectory(const FreeSpace& space,
                                                 const std::vector<mrpt::math::TPose2D>& poses);

    /// The medial-axis substitute (see above) for doors of width
    /// [minDoorWidth, maxDoorWidth] (m). Cells in raster order.
    static std::vector<cv::Point> fromMedialAxis(const FreeSpace& space, const Clearance& clearance,
                                                 double minDoorWidth, double maxDoorWidth);
    /// The same for several ranges of widths {min, max} (m) in one pass over the image: one
    /// list per range, each what fromMedialAxis() gives for it.
    static std::vector<std::vector<cv::Point>> fromMedialAxis(
        const FreeSpace& space, const Clearance& clearance,
        const std::vector<std::pair<double, double>>& widths);
};

}  // namespace toposlam::rooms
