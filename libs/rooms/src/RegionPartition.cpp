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

    touching_.assign(doors.size(), {});
    const cv::Point around[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    const cv::Rect image(0, 0, labels_.cols, labels_.rows);
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
