#pragma once
// A line segment in pixel coordinates of the map image (see GridImageFrame), as the
// virtual-door paper describes it (eqs. 3-4): its endpoints, the homogeneous line through them
// and its length.
#include <opencv2/core/types.hpp>

#include <cmath>

namespace toposlam::rooms {

struct LineSegment {
    cv::Point2f start;  ///< pixels
    cv::Point2f end;    ///< pixels

    /// Eq. 4: length in pixels.
    double length() const { return std::hypot(end.x - start.x, end.y - start.y); }
    /// Direction in [0, pi) rad, measured in the image (x right, y down).
    double direction() const {
        double a = std::atan2(end.y - start.y, end.x - start.x);
        if (a < 0)
            a += M_PI;
        if (a >= M_PI)
            a -= M_PI;
        return a;
    }
    cv::Point2f midpoint() const { return (start + end) * 0.5f; }
    /// Eq. 3: (a, b, c) = (xs, ys, 1) x (xe, ye, 1), the line a x + b y + c = 0.
    cv::Point3d homogeneous() const {
        return {static_cast<double>(start.y) - end.y, static_cast<double>(end.x) - start.x,
                static_cast<double>(start.x) * end.y - static_cast<double>(end.x) * start.y};
    }
    /// Distance (pixels) from p to the infinite line through the segment.
    double lineDistance(const cv::Point2f& p) const {
        const cv::Point3d l = homogeneous();
        const double n = std::hypot(l.x, l.y);
        return n > 0 ? std::abs(l.x * p.x + l.y * p.y + l.z) / n
                     : std::hypot(p.x - start.x, p.y - start.y);
    }
};

}  // namespace toposlam::rooms
