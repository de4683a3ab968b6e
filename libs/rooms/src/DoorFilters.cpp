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

// Whether two cuts fan out from one jamb (their other ends apart): two cross-sections of one
// opening, measured from the same jamb cell to different far cells. Cut as two 8-connected
// lines that diverge at a small angle, they touch the rooms on both sides of each other, so
// keeping both would join the rooms when the filters drop one.
bool fanFromOneJamb(const VirtualDoor& a, const VirtualDoor& b) {
    auto near = [](const cv::Point& p, const cv::Point& q) {
        return std::abs(p.x - q.x) <= 1 && std::abs(p.y - q.y) <= 1;
    };
    const cv::Point2d da = cv::Point2d(a.jambB - a.jambA) * (1.0 / a.width);
    const cv::Point2d db = cv::Point2d(b.jambB - b.jambA) * (1.0 / b.width);
    const bool shared = near(a.jambA, b.jambA) || near(a.jambB, b.jambB) ||
                        near(a.jambA, b.jambB) || near(a.jambB, b.jambA);
    return shared && std::abs(da.x * db.x + da.y * db.y) > std::cos(M_PI / 6);  // < 30 deg
}

}  // namespace

std::vector<VirtualDoor> DoorFilters::distance(std::vector<VirtualDoor> doors,
                                               double resolution) const {
    const double nd = detail::toCells(options_.frameDistance, resolution);
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

    // Groups: connected components of the "closer than N_d" relation.
    for (std::size_t i = 0; i < doors.size(); ++i)
        grid.add(doors[i], i);
    detail::DisjointSets groups(doors.size());
    for (std::size_t i = 0; i < doors.size(); ++i) {
        grid.forNeighbours(doors[i], [&](std::size_t j) {
            if (j > i && (detail::jambDistance(doors[i], doors[j]) <= nd ||
                          fanFromOneJamb(doors[i], doors[j]))) {
                groups.union_set(i, j);
            }
        });
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
