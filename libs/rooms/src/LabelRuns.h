#pragma once
// Runs of one label along a row of a CV_32S label image (internal to libs/rooms).
#include <opencv2/core/hal/intrin.hpp>

namespace toposlam::rooms::detail {

/// The end (one past the last cell) of the run of row[x]'s label that starts at x, in a row of
/// `cols` cells. Four cells at a time: a room's runs are long.
inline int runEnd(const int* row, int x, int cols) {
    const int label = row[x];
    const cv::v_int32x4 label4 = cv::v_setall_s32(label);
    for (; x + 4 <= cols; x += 4) {
        const cv::v_int32x4 other = cv::v_load(row + x) != label4;
        if (cv::v_check_any(other))
            return x + cv::v_scan_forward(other);
    }
    while (x < cols && row[x] == label)
        ++x;
    return x;
}

}  // namespace toposlam::rooms::detail
