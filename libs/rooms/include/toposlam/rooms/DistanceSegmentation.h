#pragma once
// Baseline for B4: ipa_room_segmentation's distance-transform segmentation (Bormann et al.
// 2016, sec. III-B). The free space is eroded once and distance-transformed (L2, 5x5 mask,
// rounded to 8 bit); the distance image is thresholded at every level from 255 down to 1, and
// the level whose outer contours (area minus holes) fall between the room-area limits most
// often (ties: the lower level) gives the rooms. Their contours are drawn 7 pixels thick and
// grown into the free space (wavefrontRegionGrowing), as in the package.
#include <opencv2/core/mat.hpp>

namespace toposlam::rooms {

class DistanceSegmentation {
  public:
    struct Options {
        /// Room-area limits (m^2) of the thresholded contours; the package's defaults
        /// (ros/launch/room_segmentation_action_server_params.yaml).
        double minArea = 0.35;
        double maxArea = 163.0;
    };

    DistanceSegmentation() = default;
    explicit DistanceSegmentation(const Options& options) : options_(options) {}

    /// `map`: CV_8U, 255 = free, 0 = not free; `resolution`: m per pixel.
    /// Returns CV_32S labels (see BormannBaselines.h).
    cv::Mat segment(const cv::Mat& map, double resolution) const;

  private:
    Options options_;
};

}  // namespace toposlam::rooms
