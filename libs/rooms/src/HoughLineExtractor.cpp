#include <toposlam/rooms/HoughLineExtractor.h>

#include "GridRay.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace toposlam::rooms {

std::vector<LineSegment> HoughLineExtractor::extract(const FreeSpace& space) const {
    const double res = space.frame.resolution;
    // The free region's bounding box plus the one-cell ring of wall cells around it.
    const cv::Rect roi = (space.bounds + cv::Size(2, 2) - cv::Point(1, 1)) &
                         cv::Rect(0, 0, space.free.cols, space.free.rows);
    const cv::Mat free = space.free(roi);
    cv::dilate(free, grown_, cv::Mat());       // 3x3: the 8-neighbours of free cells
    cv::bitwise_xor(grown_, free, boundary_);  // free is inside grown: xor = grown minus free
    const cv::Mat& boundary = boundary_;

    ProbabilisticHough::Parameters hough;
    hough.theta = options_.angleResolutionDeg * M_PI / 180.0;
    hough.threshold =
        std::max(2, static_cast<int>(std::lround(detail::toCells(options_.minVotesLength, res))));
    hough.minLineLength = detail::toCells(options_.minLineLength, res);
    hough.maxLineGap = detail::toCells(options_.maxLineGap, res);
    hough_.find(boundary, hough, raw_);
    std::vector<LineSegment> lines;
    lines.reserve(raw_.size());
    for (const cv::Vec4i& l : raw_) {
        lines.push_back(
            {cv::Point2f(static_cast<float>(l[0] + roi.x), static_cast<float>(l[1] + roi.y)),
             cv::Point2f(static_cast<float>(l[2] + roi.x), static_cast<float>(l[3] + roi.y))});
    }
    return lines;
}

}  // namespace toposlam::rooms
