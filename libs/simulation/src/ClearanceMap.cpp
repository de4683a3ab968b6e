#include <toposlam/simulation/ClearanceMap.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace toposlam::simulation {

ClearanceMap::ClearanceMap(const mrpt::maps::COccupancyGridMap2D& map,
                           const OccupancyThresholds& thresholds)
    : geometry_(GridGeometry::of(map)),
      classes_(geometry_.cellCount(), CellClass::Unknown),
      clearance_(geometry_.cellCount(), 0.0f) {
    const int w = geometry_.sizeX, h = geometry_.sizeY;
    // One-cell border of "not free" so that the map's edge counts as an obstacle.
    cv::Mat freeMask(h + 2, w + 2, CV_8UC1, cv::Scalar(0));
    for (int cy = 0; cy < h; ++cy) {
        for (int cx = 0; cx < w; ++cx) {
            const double p = map.getCell(cx, cy);
            CellClass c = CellClass::Unknown;
            if (p < thresholds.occupiedBelow) {
                c = CellClass::Occupied;
            } else if (p > thresholds.freeAbove) {
                c = CellClass::Free;
                freeMask.at<std::uint8_t>(cy + 1, cx + 1) = 255;
                ++freeCells_;
            }
            classes_[geometry_.index(cx, cy)] = c;
        }
    }
    // Exact Euclidean distance (in cells) from each free cell centre to the nearest non-free
    // cell centre.
    cv::Mat dist;
    cv::distanceTransform(freeMask, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
    const float res = static_cast<float>(geometry_.resolution);
    for (int cy = 0; cy < h; ++cy) {
        const float* row = dist.ptr<float>(cy + 1) + 1;
        for (int cx = 0; cx < w; ++cx) {
            const float d = row[cx];
            clearance_[geometry_.index(cx, cy)] = d > 0 ? (d - 0.5f) * res : 0.0f;
        }
    }
}

CellClass ClearanceMap::cellClass(int cx, int cy) const {
    return geometry_.contains(cx, cy) ? classes_[geometry_.index(cx, cy)] : CellClass::Unknown;
}

}  // namespace toposlam::simulation
