#pragma once
// Cells per label of a CV_32S label image (internal to libs/rooms).
#include <opencv2/core/mat.hpp>

#include <cstddef>
#include <vector>

namespace toposlam::rooms::detail {

/// area[label] += number of cells with that label (area sized beforehand to hold every label).
/// Counted per run of equal labels: one increment per cell would chain every cell of a run on
/// the same counter.
inline void countLabelAreas(const cv::Mat& labels, std::vector<int>& area) {
    for (int r = 0; r < labels.rows; ++r) {
        const int* row = labels.ptr<int>(r);
        for (int c = 0; c < labels.cols;) {
            const int label = row[c];
            const int start = c;
            while (c < labels.cols && row[c] == label)
                ++c;
            area[static_cast<std::size_t>(label)] += c - start;
        }
    }
}

}  // namespace toposlam::rooms::detail
