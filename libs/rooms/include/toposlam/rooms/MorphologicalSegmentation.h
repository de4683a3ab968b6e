#pragma once
// Baseline for B4: ipa_room_segmentation's morphological segmentation (Bormann et al. 2016,
// sec. III-A). The free space is eroded one pixel at a time (3x3, up to 73 times); after each
// erosion, every outer contour whose area (minus its holes) lies between the room-area limits
// is taken as a room and blacked out; the rooms are then drawn on the map and grown into the
// remaining free space (wavefrontRegionGrowing). Areas are of the eroded shapes.
#include <opencv2/core/mat.hpp>

namespace toposlam::rooms {

class MorphologicalSegmentation {
  public:
    struct Options {
        /// Room-area limits (m^2) of the eroded contours; the package's defaults
        /// (ros/launch/room_segmentation_action_server_params.yaml).
        double minArea = 0.8;
        double maxArea = 47.0;
        int maxErosions = 73;  ///< the package's hard-coded loop count
    };

    MorphologicalSegmentation() = default;
    explicit MorphologicalSegmentation(const Options& options) : options_(options) {}

    /// `map`: CV_8U, 255 = free, 0 = not free; `resolution`: m per pixel.
    /// Returns CV_32S labels (see BormannBaselines.h).
    cv::Mat segment(const cv::Mat& map, double resolution) const;

  private:
    Options options_;
};

}  // namespace toposlam::rooms
