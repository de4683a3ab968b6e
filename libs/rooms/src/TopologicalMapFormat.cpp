#include "TopologicalMapFormat.h"

#include <algorithm>
#include <cmath>

namespace toposlam::rooms::detail {

std::vector<long long> labelRuns(const TopologicalMap& map) {
    std::vector<long long> runs;
    if (map.labels.empty()) {
        if (map.frame.rows > 0 && map.frame.cols > 0)  // no label image: all "no room"
            runs = {0, static_cast<long long>(map.frame.rows) * map.frame.cols};
        return runs;
    }
    int current = map.labels.at<int>(0, 0);
    long long count = 0;
    for (int r = 0; r < map.labels.rows; ++r) {
        const int* row = map.labels.ptr<int>(r);
        for (int c = 0; c < map.labels.cols; ++c) {
            if (row[c] == current) {
                ++count;
                continue;
            }
            runs.insert(runs.end(), {current, count});
            current = row[c];
            count = 1;
        }
    }
    runs.insert(runs.end(), {current, count});
    return runs;
}

cv::Mat labelsFromRuns(const GridImageFrame& frame, const std::vector<long long>& runs,
                       int roomCount, const std::string& what) {
    const long long cells = static_cast<long long>(frame.rows) * frame.cols;
    if (runs.size() % 2 != 0)
        throw FormatError(what + " must hold value, count pairs");
    if (cells == 0)
        return cv::Mat();
    cv::Mat labels(frame.rows, frame.cols, CV_32S);
    long long at = 0;
    for (std::size_t k = 0; k < runs.size(); k += 2) {
        if (runs[k] < 0 || runs[k] > roomCount) {
            throw FormatError(what + ": label " + std::to_string(runs[k]) + " is not a room (0.." +
                              std::to_string(roomCount) + ")");
        }
        if (runs[k + 1] < 1 || runs[k + 1] > cells - at)
            throw FormatError(what + " cover more than rows x cols cells");
        std::fill_n(labels.ptr<int>() + at, runs[k + 1], static_cast<int>(runs[k]));
        at += runs[k + 1];
    }
    if (at != cells) {
        throw FormatError(what + " cover " + std::to_string(at) + " cells, rows x cols is " +
                          std::to_string(cells));
    }
    return labels;
}

void checkFrame(const GridImageFrame& frame) {
    if (!(frame.resolution > 0) || !std::isfinite(frame.resolution))
        throw FormatError("frame.resolution must be > 0");
    if (!std::isfinite(frame.xMin) || !std::isfinite(frame.yMin))
        throw FormatError("frame.x_min and frame.y_min must be finite");
}

}  // namespace toposlam::rooms::detail
