#pragma once
// Step 2a of the virtual-door method (sec. 1.4.1): straight wall segments by the progressive
// probabilistic Hough transform (OpenCV's HoughLinesP, computed by ProbabilisticHough) on the
// non-free cells that border the free space: the wall faces the robot saw (unknown space beyond
// them does not vote) and, on SLAM grids, also the unknown cells at the edges of shadows and of
// the unexplored space.
#include <toposlam/rooms/FreeSpaceBinarizer.h>
#include <toposlam/rooms/LineSegment.h>
#include <toposlam/rooms/ProbabilisticHough.h>

#include <opencv2/core/mat.hpp>

#include <vector>

namespace toposlam::rooms {

class HoughLineExtractor {
  public:
    struct Options {
        double angleResolutionDeg = 1.0;  ///< Hough accumulator angle step (deg)
        /// Accumulator threshold expressed as wall length (m): a line needs this many metres'
        /// worth of cells voting for it.
        double minVotesLength = 0.4;
        double minLineLength = 0.5;  ///< shortest segment returned (m)
        double maxLineGap = 0.1;     ///< largest gap bridged inside one segment (m)
    };

    HoughLineExtractor() = default;
    explicit HoughLineExtractor(const Options& options) : options_(options) {}

    /// Segments in pixel coordinates of space.frame. Only the cells next to space.free vote.
    std::vector<LineSegment> extract(const FreeSpace& space) const;

  private:
    Options options_;
    // Scratch, reused across calls.
    mutable cv::Mat grown_, boundary_;
    mutable ProbabilisticHough hough_;
    mutable std::vector<cv::Vec4i> raw_;
};

}  // namespace toposlam::rooms
