#pragma once
// How the images of libs/rooms map to the world. Every image here (free-space mask, label
// image, rendering) has one pixel per grid cell and is laid out like MRPT's
// COccupancyGridMap2D::getAsImage() and like a map PNG: column c <-> grid cell cx = c, row r <->
// grid cell cy = rows-1-r, i.e. row 0 is the top of the map (largest y).
#include <mrpt/math/TPoint2D.h>

#include <opencv2/core/types.hpp>

namespace toposlam::rooms {

struct GridImageFrame {
    double resolution = 0.05;  ///< m per cell (square cells)
    double xMin = 0.0;         ///< world x (m) of the left edge of column 0
    double yMin = 0.0;         ///< world y (m) of the bottom edge of the last row
    int cols = 0;
    int rows = 0;

    /// World position (m) of a point given in pixel coordinates, where pixel (c, r) has its
    /// centre at (c, r); fractional coordinates are allowed.
    mrpt::math::TPoint2D toWorld(double col, double row) const {
        return {xMin + (col + 0.5) * resolution, yMin + (rows - 1 - row + 0.5) * resolution};
    }
    mrpt::math::TPoint2D toWorld(const cv::Point2f& p) const { return toWorld(p.x, p.y); }
    /// Pixel coordinates (continuous; the pixel centre is integer) of a world point.
    cv::Point2f toPixel(double x, double y) const {
        return {static_cast<float>((x - xMin) / resolution - 0.5),
                static_cast<float>(rows - 1 - ((y - yMin) / resolution - 0.5))};
    }
    /// The pixel that contains a world point (may lie outside the image).
    cv::Point toCell(double x, double y) const {
        const cv::Point2f p = toPixel(x, y);
        return {cvRound(p.x), cvRound(p.y)};
    }
    bool contains(const cv::Point& p) const {
        return p.x >= 0 && p.y >= 0 && p.x < cols && p.y < rows;
    }
    double cellArea() const { return resolution * resolution; }
};

}  // namespace toposlam::rooms
