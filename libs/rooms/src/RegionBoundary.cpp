#include <toposlam/rooms/RegionBoundary.h>

#include <opencv2/core.hpp>

#include <cstdint>

namespace toposlam::rooms {

void RegionBoundary::measure(const FreeSpace& space, const RegionPartition& partition) {
    const auto regions = static_cast<std::size_t>(partition.regionCount()) + 1;
    closed_.assign(regions, 0);
    open_.assign(regions, 0);
    if (space.noWall.empty())
        return;  // every non-free cell was observed (drawn maps): nothing is open
    const cv::Mat& labels = partition.labels();
    const int rows = labels.rows, cols = labels.cols;
    // Outside: the unobserved cells (noWall, not free) connected to the edge of the image.
    cv::bitwise_and(space.noWall, ~space.free, unobserved_);
    const int n = runs_.find(unobserved_, 4);
    runs_.paint(components_);
    outside_.assign(static_cast<std::size_t>(n), 0);
    auto mark = [&](int r, int c) {
        outside_[static_cast<std::size_t>(components_.at<int>(r, c))] = 1;
    };
    for (int r = 0; r < rows; ++r) {
        mark(r, 0);
        mark(r, cols - 1);
    }
    for (int c = 0; c < cols; ++c) {
        mark(0, c);
        mark(rows - 1, c);
    }
    outside_[0] = 0;
    auto count = [&](int region, int r, int c) {
        if (r < 0 || c < 0 || r >= rows || c >= cols || space.free.at<std::uint8_t>(r, c) != 0)
            return;  // the map's edge; the region itself, another across a door cut, the cut
        const bool out = outside_[static_cast<std::size_t>(components_.at<int>(r, c))] != 0;
        ++(out ? open_ : closed_)[static_cast<std::size_t>(region)];
    };
    for (int r = 0; r < rows; ++r) {
        const int* row = labels.ptr<int>(r);
        for (int c = 0; c < cols; ++c) {
            if (row[c] == 0)
                continue;
            count(row[c], r, c - 1);
            count(row[c], r, c + 1);
            count(row[c], r - 1, c);
            count(row[c], r + 1, c);
        }
    }
}

}  // namespace toposlam::rooms
