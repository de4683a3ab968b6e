#include "RoomLabelling.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdint>
#include <deque>

namespace toposlam::rooms::detail {

namespace {

// The room with the most cells at the smallest Chebyshev distance d, 2 <= d <= reach, from
// `pocket` (whose 8-neighbours hold no room), or 0 when no room is that close. `votes` is scratch.
int nearestRoomAcrossWall(const std::vector<cv::Point>& pocket, const cv::Mat& labels, int reach,
                          std::vector<std::pair<int, int>>& votes) {
    const cv::Rect image(0, 0, labels.cols, labels.rows);
    for (int d = 2; d <= reach; ++d) {
        votes.clear();
        for (const cv::Point& p : pocket) {
            for (int k = -d; k < d; ++k) {  // the ring of side 2d + 1, each cell once
                for (const cv::Point q :
                     {cv::Point(p.x + k, p.y - d), cv::Point(p.x + d, p.y + k),
                      cv::Point(p.x - k, p.y + d), cv::Point(p.x - d, p.y - k)}) {
                    const int l = image.contains(q) ? labels.at<int>(q) : 0;
                    if (l <= 0)
                        continue;
                    auto it = std::find_if(votes.begin(), votes.end(),
                                           [l](const auto& v) { return v.first == l; });
                    if (it == votes.end())
                        votes.emplace_back(l, 1);
                    else
                        ++it->second;
                }
            }
        }
        if (!votes.empty()) {
            return std::max_element(
                       votes.begin(), votes.end(),
                       [](const auto& a, const auto& b) { return a.second < b.second; })
                ->first;
        }
    }
    return 0;
}

}  // namespace

// Region labels become room ids in place, run by run (`roomOfRegion` gives every region a room),
// and the free cells left unlabelled (the door cuts) get the label of the nearest labelled cell:
// 4-connected breadth-first growth from the labelled cells next to them, taken cut cell by cut
// cell in raster order, never leaving `free`.
void labelRooms(const cv::Mat& free, const RegionPartition& partition,
                const std::vector<int>& roomOfRegion, cv::Mat& labels) {
    for (const ConnectedRuns::Run& run : partition.regionRuns()) {
        std::fill_n(labels.ptr<int>(run.row) + run.begin, run.end - run.begin,
                    roomOfRegion[static_cast<std::size_t>(run.label)]);
    }
    const cv::Point around[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    auto inside = [&](const cv::Point& q) {
        return q.x >= 0 && q.y >= 0 && q.x < labels.cols && q.y < labels.rows;
    };
    std::deque<cv::Point> queue;
    for (const cv::Point& cut : partition.cutCells()) {
        for (const cv::Point& o : around) {
            const cv::Point q = cut + o;
            if (inside(q) && labels.at<int>(q) != 0)
                queue.push_back(q);
        }
    }
    while (!queue.empty()) {
        const cv::Point p = queue.front();
        queue.pop_front();
        const int label = labels.at<int>(p);
        for (const cv::Point& o : around) {
            const cv::Point q = p + o;
            if (!inside(q) || labels.at<int>(q) != 0 || free.at<std::uint8_t>(q) == 0)
                continue;
            labels.at<int>(q) = label;
            queue.push_back(q);
        }
    }
}

// Gives the cells of every non-free island of `space` (an obstacle that does not reach the
// map's edge: furniture, a pillar) the room around it, when all its free 4-neighbours are in
// that one room (an island between two rooms, such as a free-standing partition, stays
// unlabelled: it is a border).
void labelIslands(const FreeSpace& space, cv::Mat& labels) {
    if (space.islandRuns.empty())
        return;
    // Per island: the one room its free 4-neighbours are in, 0 while none is, kSeveral once two
    // are. Along a run only its two ends have neighbours beside it (the rest is the island).
    constexpr int kSeveral = -1;
    std::vector<int> roomOf(space.obstacleOnBorder.size(), 0);
    const int rows = labels.rows, cols = labels.cols;
    for (const ConnectedRuns::Run& run : space.islandRuns) {
        int& room = roomOf[static_cast<std::size_t>(run.label)];
        const auto vote = [&room](int neighbour) {
            if (neighbour > 0 && room != neighbour)
                room = room == 0 ? neighbour : kSeveral;
        };
        const int* here = labels.ptr<int>(run.row);
        if (run.begin > 0)
            vote(here[run.begin - 1]);
        if (run.end < cols)
            vote(here[run.end]);
        for (const int side : {run.row - 1, run.row + 1}) {
            if (side < 0 || side >= rows)
                continue;
            const int* row = labels.ptr<int>(side);
            for (int c = run.begin; c < run.end; ++c)
                vote(row[c]);
        }
    }
    for (const ConnectedRuns::Run& run : space.islandRuns) {
        const int room = roomOf[static_cast<std::size_t>(run.label)];
        if (room > 0)
            std::fill_n(labels.ptr<int>(run.row) + run.begin, run.end - run.begin, room);
    }
}

// Gives each free pocket outside the segmented free space (`otherFree`: no 4-connected way in)
// of at most `maxCells` cells the room it touches, when its 8-neighbours hold exactly one room.
// Such pockets are mostly drawing artefacts: free cells caught between the steps of a wall
// rasterised at an angle. A pocket whose 8-neighbours hold no room at all lies inside a wall
// (on SLAM grids: cells a few grazing or noisy rays went through) and takes the nearest room
// within `wallReach` cells (0: none), whatever its size if it is a line. Larger pockets, those
// between two rooms, and those reaching the edge of the (cropped) image, which may go on beyond
// it, stay unlabelled. `cells`, `pocket` and `votes` are scratch.
void labelSlivers(const cv::Mat& otherFree, const std::vector<cv::Point>& cells,
                  std::size_t maxCells, int wallReach, cv::Mat& labels,
                  std::vector<cv::Point>& pocket, std::vector<std::pair<int, int>>& votes) {
    constexpr int kVisited = -1, kLeft = -2;  // in this pocket; in a pocket left unlabelled
    const cv::Rect image(0, 0, labels.cols, labels.rows);
    for (const cv::Point& seed : cells) {
        if (labels.at<int>(seed) != 0)
            continue;  // visited (or labelled: islands never are free)
        pocket.assign(1, seed);
        labels.at<int>(seed) = kVisited;
        int room = 0;
        bool oneRoom = true, atEdge = false;
        for (std::size_t k = 0; k < pocket.size(); ++k) {
            const cv::Point p = pocket[k];
            if (p.x == 0 || p.y == 0 || p.x == labels.cols - 1 || p.y == labels.rows - 1)
                atEdge = true;  // it may go on beyond the image
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const cv::Point q(p.x + dx, p.y + dy);
                    if (!image.contains(q))
                        continue;
                    const int l = labels.at<int>(q);
                    if (l > 0) {
                        oneRoom = oneRoom && (room == 0 || room == l);
                        room = l;
                    } else if (l == 0 && otherFree.at<std::uint8_t>(q) != 0) {
                        labels.at<int>(q) = kVisited;
                        pocket.push_back(q);
                    }
                }
            }
        }
        bool fits = pocket.size() <= maxCells;
        if (room == 0 && !atEdge && wallReach > 0) {
            // Inside a wall a pocket may run the wall's whole length: a line of at most three
            // cells across on average (walls are a few cells thick) is no room, however long.
            const cv::Rect box = cv::boundingRect(pocket);
            fits = fits ||
                   pocket.size() <= 3 * static_cast<std::size_t>(std::max(box.width, box.height));
            if (fits)
                room = nearestRoomAcrossWall(pocket, labels, wallReach, votes);
        }
        const int label = fits && !atEdge && oneRoom && room > 0 ? room : kLeft;
        for (const cv::Point& p : pocket)
            labels.at<int>(p) = label;
    }
    for (const cv::Point& p : cells) {
        if (labels.at<int>(p) == kLeft)
            labels.at<int>(p) = 0;
    }
}

}  // namespace toposlam::rooms::detail
