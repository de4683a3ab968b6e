#include <toposlam/rooms/SegmentationMetrics.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdint>
#include <deque>
#include <limits>
#include <map>
#include <unordered_map>

namespace toposlam::rooms {

GroundTruthRooms groundTruthRooms(const cv::Mat& groundTruthGrey) {
    CV_Assert(groundTruthGrey.type() == CV_8U);
    cv::Mat white;
    cv::threshold(groundTruthGrey, white, 250, 255, cv::THRESH_BINARY);
    cv::Mat components, stats, centroids;
    const int n = cv::connectedComponentsWithStats(white, components, stats, centroids, 8, CV_32S);
    std::vector<int> renumber(static_cast<std::size_t>(n), 0);
    GroundTruthRooms out;
    for (int i = 1; i < n; ++i) {
        if (stats.at<int>(i, cv::CC_STAT_AREA) > kMaxIgnoredRegionPixels) {
            renumber[static_cast<std::size_t>(i)] = ++out.count;
        }
    }
    out.labels = cv::Mat(components.size(), CV_32S);
    for (int r = 0; r < components.rows; ++r) {
        const int* in = components.ptr<int>(r);
        int* o = out.labels.ptr<int>(r);
        for (int c = 0; c < components.cols; ++c)
            o[c] = renumber[static_cast<std::size_t>(in[c])];
    }
    return out;
}

GroundTruthRooms groundTruthFromLabels(const cv::Mat& roomLabels) {
    CV_Assert(roomLabels.type() == CV_32S);
    std::map<int, int> size;
    for (int r = 0; r < roomLabels.rows; ++r) {
        const int* row = roomLabels.ptr<int>(r);
        for (int c = 0; c < roomLabels.cols; ++c) {
            if (row[c] != 0)
                ++size[row[c]];
        }
    }
    GroundTruthRooms out;
    std::unordered_map<int, int> renumber;
    for (const auto& [label, pixels] : size) {
        if (pixels > kMaxIgnoredRegionPixels)
            renumber[label] = ++out.count;
    }
    out.labels = cv::Mat(roomLabels.size(), CV_32S);
    for (int r = 0; r < roomLabels.rows; ++r) {
        const int* in = roomLabels.ptr<int>(r);
        int* o = out.labels.ptr<int>(r);
        for (int c = 0; c < roomLabels.cols; ++c) {
            const auto it = renumber.find(in[c]);
            o[c] = it == renumber.end() ? 0 : it->second;
        }
    }
    return out;
}

GroundTruthRooms openFloorOfRooms(const GroundTruthRooms& truth, const cv::Mat& free) {
    CV_Assert(free.type() == CV_8U && free.size() == truth.labels.size());
    cv::Mat open;
    // Pixels outside the image count as free: a room at the border keeps its border pixels.
    cv::erode(free != 0, open, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3)),
              cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(255));
    std::vector<int> openPixels(static_cast<std::size_t>(truth.count) + 1, 0);
    for (int r = 0; r < open.rows; ++r) {
        const int* label = truth.labels.ptr<int>(r);
        const auto* o = open.ptr<std::uint8_t>(r);
        for (int c = 0; c < open.cols; ++c)
            openPixels[static_cast<std::size_t>(label[c])] += o[c] != 0;
    }
    GroundTruthRooms out{truth.labels.clone(), truth.count};
    for (int r = 0; r < open.rows; ++r) {
        int* label = out.labels.ptr<int>(r);
        const auto* o = open.ptr<std::uint8_t>(r);
        for (int c = 0; c < open.cols; ++c) {
            if (o[c] == 0 &&
                openPixels[static_cast<std::size_t>(label[c])] > kMaxIgnoredRegionPixels)
                label[c] = 0;
        }
    }
    return out;
}

PrecisionRecall bormannPrecisionRecall(const GroundTruthRooms& truth, const cv::Mat& segmentation) {
    CV_Assert(segmentation.type() == CV_32S && segmentation.size() == truth.labels.size());
    // Segment label -> dense index; per segment its size and its overlap with every GT room.
    std::unordered_map<int, std::size_t> index;
    std::vector<std::size_t> segmentSize;
    std::vector<std::vector<std::size_t>> overlap;  // [segment][room]
    std::vector<std::size_t> roomSize(static_cast<std::size_t>(truth.count) + 1, 0);
    for (int r = 0; r < segmentation.rows; ++r) {
        const int* seg = segmentation.ptr<int>(r);
        const int* gt = truth.labels.ptr<int>(r);
        for (int c = 0; c < segmentation.cols; ++c) {
            ++roomSize[static_cast<std::size_t>(gt[c])];
            if (seg[c] == 0)
                continue;
            auto [it, inserted] = index.try_emplace(seg[c], segmentSize.size());
            if (inserted) {
                segmentSize.push_back(0);
                overlap.emplace_back(static_cast<std::size_t>(truth.count) + 1, 0);
            }
            ++segmentSize[it->second];
            ++overlap[it->second][static_cast<std::size_t>(gt[c])];
        }
    }
    PrecisionRecall out;
    out.rooms = truth.count;
    std::vector<bool> scored(segmentSize.size());
    for (std::size_t s = 0; s < segmentSize.size(); ++s) {
        scored[s] = segmentSize[s] > static_cast<std::size_t>(kMaxIgnoredRegionPixels);
    }
    double recallSum = 0, recallCovered = 0, recallTotal = 0;
    for (int g = 1; g <= truth.count; ++g) {
        std::size_t best = 0;
        for (std::size_t s = 0; s < segmentSize.size(); ++s) {
            if (scored[s])
                best = std::max(best, overlap[s][static_cast<std::size_t>(g)]);
        }
        const double size = static_cast<double>(roomSize[static_cast<std::size_t>(g)]);
        out.roomRecall.push_back(static_cast<double>(best) / size);
        out.roomPixels.push_back(roomSize[static_cast<std::size_t>(g)]);
        recallSum += static_cast<double>(best) / size;
        recallCovered += static_cast<double>(best);
        recallTotal += size;
    }
    const auto unassigned = index.find(kUnassignedLabel);
    double precisionSum = 0, precisionCovered = 0, precisionTotal = 0, roomsPrecisionSum = 0;
    int roomSegments = 0;
    for (std::size_t s = 0; s < segmentSize.size(); ++s) {
        if (!scored[s])
            continue;
        ++out.segments;
        std::size_t best = 0;
        for (int g = 1; g <= truth.count; ++g)
            best = std::max(best, overlap[s][static_cast<std::size_t>(g)]);
        const double precision = static_cast<double>(best) / static_cast<double>(segmentSize[s]);
        precisionSum += precision;
        precisionCovered += static_cast<double>(best);
        precisionTotal += static_cast<double>(segmentSize[s]);
        if (unassigned != index.end() && unassigned->second == s) {
            out.unassignedPixels = segmentSize[s];
        } else {
            roomsPrecisionSum += precision;
            ++roomSegments;
        }
    }
    if (roomSegments > 0)
        out.precisionOfRooms = roomsPrecisionSum / roomSegments;
    if (truth.count > 0) {
        out.recall = recallSum / truth.count;
        out.recallPixels = recallCovered / recallTotal;
    }
    if (out.segments > 0) {
        out.precision = precisionSum / out.segments;
        out.precisionPixels = precisionCovered / precisionTotal;
    }
    return out;
}

int countSegments(const cv::Mat& segmentation) {
    std::vector<int> labels;
    for (int r = 0; r < segmentation.rows; ++r) {
        const int* row = segmentation.ptr<int>(r);
        for (int c = 0; c < segmentation.cols; ++c) {
            if (row[c] != 0 && row[c] != kUnassignedLabel)
                labels.push_back(row[c]);
        }
    }
    std::sort(labels.begin(), labels.end());
    return static_cast<int>(std::unique(labels.begin(), labels.end()) - labels.begin());
}

cv::Mat doorMetricSegmentLabels(const cv::Mat& segmentation) {
    std::unordered_map<int, int> size;
    for (int r = 0; r < segmentation.rows; ++r) {
        const int* row = segmentation.ptr<int>(r);
        for (int c = 0; c < segmentation.cols; ++c)
            ++size[row[c]];
    }
    cv::Mat out = segmentation.clone();
    for (int r = 0; r < out.rows; ++r) {
        int* row = out.ptr<int>(r);
        for (int c = 0; c < out.cols; ++c) {
            if (row[c] == kUnassignedLabel || size[row[c]] <= kMaxIgnoredRegionPixels)
                row[c] = 0;
        }
    }
    return out;
}

std::vector<LabelBoundaryDoor> labelBoundaryDoors(const cv::Mat& labelsIn, const cv::Mat& free,
                                                  int gapSteps) {
    CV_Assert(labelsIn.type() == CV_32S && free.type() == CV_8U && free.size() == labelsIn.size());
    const int rows = labelsIn.rows, cols = labelsIn.cols;
    // 2. Gap filling: FIFO multi-source BFS, seeds in raster order, at most gapSteps steps.
    cv::Mat labels = labelsIn.clone();
    cv::Mat steps(rows, cols, CV_32S, cv::Scalar(0));
    std::deque<cv::Point> queue;
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {
            if (labels.at<int>(r, c) > 0)
                queue.emplace_back(c, r);
        }
    }
    const cv::Point around[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    while (!queue.empty()) {
        const cv::Point p = queue.front();
        queue.pop_front();
        const int s = steps.at<int>(p);
        if (s >= gapSteps)
            continue;
        for (const cv::Point& o : around) {
            const cv::Point q = p + o;
            if (q.x < 0 || q.y < 0 || q.x >= cols || q.y >= rows)
                continue;
            if (labels.at<int>(q) != 0 || free.at<std::uint8_t>(q) == 0)
                continue;
            labels.at<int>(q) = labels.at<int>(p);
            steps.at<int>(q) = s + 1;
            queue.push_back(q);
        }
    }
    // 3-4. Boundary pixels per unordered label pair.
    std::map<std::pair<int, int>, std::vector<long long>> pairs;
    auto add = [&](int a, int b, long long pa, long long pb) {
        auto& v = pairs[{std::min(a, b), std::max(a, b)}];
        v.push_back(pa);
        v.push_back(pb);
    };
    for (int r = 0; r < rows; ++r) {
        const int* row = labels.ptr<int>(r);
        const int* below = r + 1 < rows ? labels.ptr<int>(r + 1) : nullptr;
        for (int c = 0; c < cols; ++c) {
            const int a = row[c];
            if (a <= 0)
                continue;
            const long long pa = static_cast<long long>(r) * cols + c;
            if (c + 1 < cols && row[c + 1] > 0 && row[c + 1] != a)
                add(a, row[c + 1], pa, pa + 1);
            if (below && below[c] > 0 && below[c] != a)
                add(a, below[c], pa, pa + cols);
        }
    }
    // 5. Representative point: nearest to the mean, first in raster order on ties.
    std::vector<LabelBoundaryDoor> doors;
    for (auto& [key, raster] : pairs) {
        std::sort(raster.begin(), raster.end());
        raster.erase(std::unique(raster.begin(), raster.end()), raster.end());
        LabelBoundaryDoor d;
        d.labelA = key.first;
        d.labelB = key.second;
        double mx = 0, my = 0;
        for (long long i : raster) {
            d.pixels.emplace_back(static_cast<int>(i % cols), static_cast<int>(i / cols));
            mx += d.pixels.back().x;
            my += d.pixels.back().y;
        }
        mx /= static_cast<double>(d.pixels.size());
        my /= static_cast<double>(d.pixels.size());
        double best = std::numeric_limits<double>::max();
        for (const cv::Point& p : d.pixels) {
            const double dist = (p.x - mx) * (p.x - mx) + (p.y - my) * (p.y - my);
            if (dist < best) {
                best = dist;
                d.representative = p;
            }
        }
        doors.push_back(std::move(d));
    }
    return doors;
}

DoorMatchCounts matchDoors(const std::vector<LabelBoundaryDoor>& virtualDoors,
                           const std::vector<LabelBoundaryDoor>& trueDoors,
                           double tolerancePixels) {
    DoorMatchCounts out;
    out.virtualDoors = virtualDoors.size();
    out.trueDoors = trueDoors.size();
    const double tol2 = tolerancePixels * tolerancePixels;
    std::vector<bool> trueMatched(trueDoors.size(), false);
    for (const LabelBoundaryDoor& v : virtualDoors) {
        bool matched = false;
        for (std::size_t t = 0; t < trueDoors.size(); ++t) {
            for (const cv::Point& p : trueDoors[t].pixels) {
                const double dx = p.x - v.representative.x, dy = p.y - v.representative.y;
                if (dx * dx + dy * dy <= tol2) {
                    matched = true;
                    trueMatched[t] = true;
                    break;
                }
            }
        }
        if (matched)
            ++out.matchedVirtual;
    }
    out.matchedTrue =
        static_cast<std::size_t>(std::count(trueMatched.begin(), trueMatched.end(), true));
    return out;
}

}  // namespace toposlam::rooms
