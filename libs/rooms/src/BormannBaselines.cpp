#include <toposlam/rooms/BormannBaselines.h>
#include <toposlam/rooms/SegmentationMetrics.h>

#include <vector>

namespace toposlam::rooms {

void wavefrontRegionGrowing(cv::Mat& labels) {
    CV_Assert(labels.type() == CV_32S);
    // The package repeats full Jacobi passes; one pass assigns exactly the unassigned pixels
    // that have a labelled neighbour in the previous state. Visiting only those pixels, layer
    // by layer, gives the same image.
    const int rows = labels.rows, cols = labels.cols;
    auto unassigned = [&](int r, int c) {
        return r >= 1 && c >= 1 && r < rows - 1 && c < cols - 1 &&
               labels.at<int>(r, c) >= kUnassignedLabel;
    };
    auto firstLabelAround = [&](int r, int c) {
        for (int dr = -1; dr <= 1; ++dr) {
            for (int dc = -1; dc <= 1; ++dc) {
                const int v = labels.at<int>(r + dr, c + dc);
                if (v != 0 && v < kUnassignedLabel)
                    return v;
            }
        }
        return 0;
    };
    cv::Mat queued(rows, cols, CV_8U, cv::Scalar(0));
    std::vector<cv::Point> layer;
    for (int r = 1; r < rows - 1; ++r) {
        for (int c = 1; c < cols - 1; ++c) {
            if (unassigned(r, c) && firstLabelAround(r, c) != 0) {
                layer.emplace_back(c, r);
                queued.at<std::uint8_t>(r, c) = 1;
            }
        }
    }
    std::vector<int> values;
    std::vector<cv::Point> next;
    while (!layer.empty()) {
        values.resize(layer.size());
        for (std::size_t i = 0; i < layer.size(); ++i)
            values[i] = firstLabelAround(layer[i].y, layer[i].x);
        for (std::size_t i = 0; i < layer.size(); ++i)
            labels.at<int>(layer[i]) = values[i];
        next.clear();
        for (const cv::Point& p : layer) {
            for (int dr = -1; dr <= 1; ++dr) {
                for (int dc = -1; dc <= 1; ++dc) {
                    const int r = p.y + dr, c = p.x + dc;
                    if (!unassigned(r, c) || queued.at<std::uint8_t>(r, c))
                        continue;
                    queued.at<std::uint8_t>(r, c) = 1;
                    next.emplace_back(c, r);
                }
            }
        }
        // Raster order is irrelevant (values come from the previous layer's state).
        layer.swap(next);
    }
}

}  // namespace toposlam::rooms
