// The paper's distance and adjacency filters (DoorFilters.h); the wall-jamb test, the
// constriction test and the minimum-area filter have a file each (DoorFilters<Name>.cpp).
#include <toposlam/rooms/DoorFilters.h>

#include "DoorNeighbours.h"
#include "GridRay.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace toposlam::rooms {

namespace {

// Cuts that fan out from one jamb cell are cross-sections of one opening, not two doors, when
// they diverge by less than kNarrowFan, or by less than kWideFan where the far side of the
// triangle they span is wall. Two cuts at most a door wide, 60 degrees apart or less, span a
// triangle whose far side is at most a door wide too: never a room. Keeping both leaves that
// triangle as a sliver the area filter joins to both sides, taking both cuts away (a door at a
// wall's end beside an outer wall, cut also diagonally to that wall). Where the far side is
// open (a third opening: three doors meeting at a wall's end) the triangle is a hub between
// doors and both cuts stay. Narrow fans are always one opening: as 8-connected lines they
// touch the rooms on both sides of each other.
constexpr double kNarrowFan = M_PI / 6, kWideFan = M_PI / 3;
// m: how far beyond the middle of the triangle's far side free cells make it open: half the
// narrowest door (0.6 m) across a third opening.
constexpr double kOpenBeyond = 0.3;

bool fanFromOneJamb(const cv::Mat& free, const VirtualDoor& a, const VirtualDoor& b,
                    double openBeyondCells) {
    auto near = [](const cv::Point& p, const cv::Point& q) {
        return std::abs(p.x - q.x) <= 1 && std::abs(p.y - q.y) <= 1;
    };
    auto fan = [&](const cv::Point& sharedA, const cv::Point& farA, const cv::Point& sharedB,
                   const cv::Point& farB) {
        if (!near(sharedA, sharedB))
            return false;
        const cv::Point2d ua = cv::Point2d(farA - sharedA) * (1.0 / a.width);
        const cv::Point2d ub = cv::Point2d(farB - sharedB) * (1.0 / b.width);
        const double cosine = ua.x * ub.x + ua.y * ub.y;
        if (!(cosine > std::cos(kWideFan)))
            return false;
        if (cosine > std::cos(kNarrowFan))
            return true;
        // From the middle of the far side, away from the shared jamb: wall within reach?
        const cv::Point2d middle = 0.5 * (cv::Point2d(farA) + cv::Point2d(farB));
        cv::Point2d out = middle - cv::Point2d(sharedA);
        const double length = std::hypot(out.x, out.y);
        if (length <= 0)
            return true;
        out *= 1.0 / length;
        cv::Point hit;
        return detail::walkRay(
            cv::Point(static_cast<int>(std::lround(middle.x)),
                      static_cast<int>(std::lround(middle.y))),
            out.x, out.y, openBeyondCells, [&](int x, int y) { return !detail::isSet(free, x, y); },
            hit);
    };
    return fan(a.jambA, a.jambB, b.jambA, b.jambB) || fan(a.jambB, a.jambA, b.jambB, b.jambA) ||
           fan(a.jambA, a.jambB, b.jambB, b.jambA) || fan(a.jambB, a.jambA, b.jambA, b.jambB);
}

}  // namespace

std::vector<VirtualDoor> DoorFilters::distance(const FreeSpace& space,
                                               std::vector<VirtualDoor> doors) const {
    const double resolution = space.frame.resolution;
    const double nd = detail::toCells(options_.frameDistance, resolution);
    const double openBeyond = detail::toCells(kOpenBeyond, resolution);
    detail::MidpointBuckets grid(nd);

    if (!options_.keepNarrowestOfGroup) {  // the paper: greedy, in search order
        std::vector<VirtualDoor> kept;
        for (const VirtualDoor& d : doors) {
            bool tooClose = false;
            grid.forNeighbours(d, [&](std::size_t j) {
                tooClose = tooClose || detail::jambDistance(d, kept[j]) <= nd;
            });
            if (tooClose)
                continue;
            grid.add(d, kept.size());
            kept.push_back(d);
        }
        return kept;
    }

    // Groups: connected components of the "closer than N_d" relation and of fans from one jamb
    // (whose middles may lie up to half a door's width apart, farther than N_d: found through
    // the jamb cells).
    auto cellKey = [](const cv::Point& p) {
        return static_cast<long long>(p.y) * (1LL << 32) + static_cast<long long>(p.x);
    };
    std::vector<std::pair<long long, std::size_t>> byJamb;  // (jamb cell, door), sorted
    byJamb.reserve(2 * doors.size());
    for (std::size_t i = 0; i < doors.size(); ++i) {
        grid.add(doors[i], i);
        byJamb.emplace_back(cellKey(doors[i].jambA), i);
        byJamb.emplace_back(cellKey(doors[i].jambB), i);
    }
    std::sort(byJamb.begin(), byJamb.end());
    detail::DisjointSets groups(doors.size());
    for (std::size_t i = 0; i < doors.size(); ++i) {
        grid.forNeighbours(doors[i], [&](std::size_t j) {
            if (j > i && detail::jambDistance(doors[i], doors[j]) <= nd)
                groups.union_set(i, j);
        });
        for (const cv::Point& jamb : {doors[i].jambA, doors[i].jambB}) {
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const long long key = cellKey(jamb + cv::Point(dx, dy));
                    auto k = std::lower_bound(byJamb.begin(), byJamb.end(),
                                              std::pair<long long, std::size_t>(key, 0));
                    for (; k != byJamb.end() && k->first == key; ++k) {
                        const std::size_t j = k->second;
                        if (j > i && fanFromOneJamb(space.free, doors[i], doors[j], openBeyond))
                            groups.union_set(i, j);
                    }
                }
            }
        }
    }
    std::unordered_map<std::size_t, std::vector<std::size_t>> members;
    for (std::size_t i = 0; i < doors.size(); ++i)
        members[groups.find_set(i)].push_back(i);
    std::vector<std::size_t> chosen;
    for (auto& [root, group] : members) {
        (void)root;
        double narrowest = 1e18;
        for (std::size_t i : group)
            narrowest = std::min(narrowest, doors[i].width);
        cv::Point2d middle(0, 0);
        for (std::size_t i : group)
            middle += 0.5 * (cv::Point2d(doors[i].jambA) + cv::Point2d(doors[i].jambB));
        middle *= 1.0 / static_cast<double>(group.size());
        std::size_t best = group.front();
        double bestOffset = 1e18;
        for (std::size_t i : group) {
            if (doors[i].width > narrowest + 0.5)
                continue;  // half a cell: same width
            const cv::Point2d m = 0.5 * (cv::Point2d(doors[i].jambA) + cv::Point2d(doors[i].jambB));
            const double offset = std::hypot(m.x - middle.x, m.y - middle.y);
            if (offset < bestOffset) {
                bestOffset = offset;
                best = i;
            }
        }
        chosen.push_back(best);
    }
    std::sort(chosen.begin(), chosen.end());  // keep the search order
    std::vector<VirtualDoor> kept;
    kept.reserve(chosen.size());
    for (std::size_t i : chosen)
        kept.push_back(doors[i]);
    return kept;
}

std::vector<std::size_t> DoorFilters::adjacency(const RegionPartition& partition) {
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < partition.doorCount(); ++i) {
        if (partition.regionsAt(i).size() >= 2)
            kept.push_back(i);
    }
    return kept;
}

}  // namespace toposlam::rooms
