#include <toposlam/rooms/RegionPartition.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdint>

namespace toposlam::rooms {

void RegionPartition::compute(const cv::Mat& free, const std::vector<VirtualDoor>& doors) {
    free.copyTo(open_);
    for (const VirtualDoor& d : doors)
        cv::line(open_, d.jambA, d.jambB, cv::Scalar(0), 1, cv::LINE_8);
    regionCount_ = runs_.find(open_, 4) - 1;
    runs_.paint(labels_);
    areas_ = runs_.areas();
    // The cut cells: free, and zero in open_, within each door line's box.
    const cv::Rect image(0, 0, free.cols, free.rows);
    cutCells_.clear();
    for (const VirtualDoor& d : doors) {
        const cv::Point lo(std::min(d.jambA.x, d.jambB.x), std::min(d.jambA.y, d.jambB.y));
        const cv::Point hi(std::max(d.jambA.x, d.jambB.x), std::max(d.jambA.y, d.jambB.y));
        const cv::Rect box = cv::Rect(lo, hi + cv::Point(1, 1)) & image;
        for (int r = box.y; r < box.br().y; ++r) {
            const auto* f = free.ptr<std::uint8_t>(r);
            const auto* o = open_.ptr<std::uint8_t>(r);
            for (int c = box.x; c < box.br().x; ++c) {
                if (f[c] != 0 && o[c] == 0)
                    cutCells_.emplace_back(c, r);
            }
        }
    }
    std::sort(cutCells_.begin(), cutCells_.end(), [](const cv::Point& a, const cv::Point& b) {
        return a.y != b.y ? a.y < b.y : a.x < b.x;
    });
    cutCells_.erase(std::unique(cutCells_.begin(), cutCells_.end()), cutCells_.end());

    touching_.assign(doors.size(), {});
    const cv::Point around[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    std::vector<std::pair<int, int>> counts;
    for (std::size_t i = 0; i < doors.size(); ++i) {
        counts.clear();
        cv::LineIterator it(labels_, doors[i].jambA, doors[i].jambB, 8);
        for (int k = 0; k < it.count; ++k, ++it) {
            for (const cv::Point& o : around) {
                const cv::Point q = it.pos() + o;
                if (!image.contains(q))
                    continue;
                const int label = labels_.at<int>(q);
                if (label == 0)
                    continue;
                auto found = std::find_if(counts.begin(), counts.end(),
                                          [label](const auto& c) { return c.first == label; });
                if (found == counts.end()) {
                    counts.emplace_back(label, 1);
                } else {
                    ++found->second;
                }
            }
        }
        std::sort(counts.begin(), counts.end(), [](const auto& a, const auto& b) {
            return a.second != b.second ? a.second > b.second : a.first < b.first;
        });
        touching_[i] = counts;
    }
}

}  // namespace toposlam::rooms
