#pragma once
// The 5x5 chamfer distance transform (internal to libs/rooms).
#include <opencv2/core/mat.hpp>

#include <vector>

namespace toposlam::rooms::detail {

/// The same image as cv::distanceTransform(free, out, cv::DIST_L2, cv::DIST_MASK_5), to the bit
/// (Borgefors' 5x5 chamfer, weights 1 / 1.4 / 2.1969 in OpenCV's 16.16 fixed point; outside the
/// image is far, not an obstacle), in 40 % of the time: OpenCV walks a full-size integer image
/// twice, one pixel at a time; here every term is taken four pixels at a time (the one from the
/// pixel left (right) of it as a running minimum inside each block of four, then the block
/// before it), and the integer distances live in `out` itself between the passes, with the last
/// three rows in `rowsScratch`. `free`: CV_8U, non-zero = free; `out`: CV_32F, pixels.
void chamferDistance5x5(const cv::Mat& free, cv::Mat& out, std::vector<int>& rowsScratch);

}  // namespace toposlam::rooms::detail
