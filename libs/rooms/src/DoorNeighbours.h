#pragma once
// Doors near each other (internal to libs/rooms): how far apart two doors' jambs are, and doors
// bucketed so that the near ones are found without comparing every pair. Shared by the distance
// filter and the constriction test (DoorFilters).
#include <toposlam/rooms/VirtualDoorDetector.h>

#include "GridRay.h"

#include <boost/pending/disjoint_sets.hpp>
#include <opencv2/core/types.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <unordered_map>
#include <vector>

namespace toposlam::rooms::detail {

// Union-find over 0..n-1 (union by rank, path compression).
using DisjointSets = boost::disjoint_sets_with_storage<>;

/// Cells between the jambs of two doors: the larger of the two jamb-to-jamb distances, paired
/// the way that makes it smallest.
inline double jambDistance(const VirtualDoor& a, const VirtualDoor& b) {
    auto d = [](const cv::Point& p, const cv::Point& q) {
        return detail::cellDistance(p.x - q.x, p.y - q.y);
    };
    return std::min(std::max(d(a.jambA, b.jambA), d(a.jambB, b.jambB)),
                    std::max(d(a.jambA, b.jambB), d(a.jambB, b.jambA)));
}

/// Doors bucketed by the midpoints of their jambs on a grid of `size` cells: doors whose jambs
/// are within `size` of each other's have midpoints within `size`, so only the neighbouring
/// buckets need comparing.
class MidpointBuckets {
  public:
    explicit MidpointBuckets(double size) : size_(std::max(1.0, size)) {}
    void add(const VirtualDoor& d, std::size_t index) {
        const cv::Point b = bucketOf(d);
        grid_[keyOf(b.x, b.y)].push_back(index);
    }
    /// Calls f(index) for every door added in the 3 x 3 buckets around d's.
    template <class F>
    void forNeighbours(const VirtualDoor& d, F&& f) const {
        const cv::Point b = bucketOf(d);
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                auto it = grid_.find(keyOf(b.x + dx, b.y + dy));
                if (it == grid_.end())
                    continue;
                for (std::size_t j : it->second)
                    f(j);
            }
        }
    }

  private:
    // Buckets left of or above the image are negative: shifted as unsigned (a negative value
    // shifted left is undefined).
    static long long keyOf(int bx, int by) {
        return static_cast<long long>(
            (static_cast<unsigned long long>(static_cast<unsigned>(bx)) << 32) |
            static_cast<unsigned>(by));
    }
    cv::Point bucketOf(const VirtualDoor& d) const {
        const cv::Point2d m = 0.5 * (cv::Point2d(d.jambA) + cv::Point2d(d.jambB));
        return cv::Point(static_cast<int>(std::floor(m.x / size_)),
                         static_cast<int>(std::floor(m.y / size_)));
    }
    double size_;
    std::unordered_map<long long, std::vector<std::size_t>> grid_;
};

}  // namespace toposlam::rooms::detail
