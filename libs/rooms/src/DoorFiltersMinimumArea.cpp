// The minimum-area filter of the door filters (DoorFilters.h): regions too small for a room
// (or mostly open to the unobserved outside) are merged into a neighbour through a door.
#include <toposlam/rooms/DoorFilters.h>

#include "DoorNeighbours.h"
#include "GridRay.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace toposlam::rooms {

namespace {

// The regions of a partition merged through removed doors (the minimum-area filter's state):
// a union-find over the regions with each set's area at its representative, and which of the
// candidate doors are removed.
class RegionMerge {
  public:
    RegionMerge(const RegionPartition& partition, const std::vector<std::size_t>& candidates,
                const RegionBoundary* boundary)
        : partition_(partition),
          candidates_(candidates),
          sets_(static_cast<std::size_t>(partition.regionCount()) + 1),
          area_(partition.areas().begin(), partition.areas().end()),
          closed_(area_.size(), 0),
          open_(area_.size(), 0),
          removed_(candidates.size(), false) {
        if (boundary != nullptr) {
            closed_.assign(boundary->closed().begin(), boundary->closed().end());
            open_.assign(boundary->open().begin(), boundary->open().end());
        }
    }

    int rootOf(int region) {
        return static_cast<int>(sets_.find_set(static_cast<std::size_t>(region)));
    }
    double area(int root) const { return area_[static_cast<std::size_t>(root)]; }
    /// Whether more than `maxFraction` of the set's boundary is open to the unobserved
    /// outside (RegionBoundary).
    bool mostlyOpen(int root, double maxFraction) const {
        const auto i = static_cast<std::size_t>(root);
        return open_[i] > maxFraction * (closed_[i] + open_[i]);
    }
    bool removed(std::size_t k) const { return removed_[k]; }
    std::size_t size() const { return candidates_.size(); }
    int sideA(std::size_t k) const { return partition_.regionsAt(candidates_[k])[0].first; }
    int sideB(std::size_t k) const { return partition_.regionsAt(candidates_[k])[1].first; }
    /// The sets on the two sides of candidate k.
    std::pair<int, int> liveSides(std::size_t k) { return {rootOf(sideA(k)), rootOf(sideB(k))}; }

    /// Removes candidate k and joins every region it touches.
    void removeDoor(std::size_t k) {
        removed_[k] = true;
        for (const auto& [region, contacts] : partition_.regionsAt(candidates_[k])) {
            (void)contacts;
            join(sideA(k), region);
        }
    }

    /// Whether candidate k still touches three or more sets (crossing cuts).
    bool touchesMoreThanTwo(std::size_t k) {
        std::vector<int> roots;
        for (const auto& [region, contacts] : partition_.regionsAt(candidates_[k])) {
            (void)contacts;
            roots.push_back(rootOf(region));
        }
        std::sort(roots.begin(), roots.end());
        return std::unique(roots.begin(), roots.end()) - roots.begin() > 2;
    }

    DoorFilters::Rooms rooms() {
        const int regions = partition_.regionCount();
        DoorFilters::Rooms out;
        out.roomOfRegion.assign(static_cast<std::size_t>(regions) + 1, 0);
        std::vector<int> roomOfRoot(static_cast<std::size_t>(regions) + 1, 0);
        for (int r = 1; r <= regions; ++r) {
            int& room = roomOfRoot[static_cast<std::size_t>(rootOf(r))];
            if (room == 0)
                room = ++out.roomCount;
            out.roomOfRegion[static_cast<std::size_t>(r)] = room;
        }
        for (std::size_t k = 0; k < candidates_.size(); ++k) {
            if (removed_[k])
                continue;
            const int a = out.roomOfRegion[static_cast<std::size_t>(sideA(k))];
            const int b = out.roomOfRegion[static_cast<std::size_t>(sideB(k))];
            if (a != b)
                out.doors.push_back({candidates_[k], std::min(a, b), std::max(a, b)});
        }
        return out;
    }

  private:
    void join(int a, int b) {
        a = rootOf(a);
        b = rootOf(b);
        if (a == b)
            return;
        const double total = area(a) + area(b);
        const double closed =
            closed_[static_cast<std::size_t>(a)] + closed_[static_cast<std::size_t>(b)];
        const double open = open_[static_cast<std::size_t>(a)] + open_[static_cast<std::size_t>(b)];
        sets_.link(static_cast<std::size_t>(a), static_cast<std::size_t>(b));
        const auto root = static_cast<std::size_t>(rootOf(a));
        area_[root] = total;
        closed_[root] = closed;
        open_[root] = open;
    }

    const RegionPartition& partition_;
    const std::vector<std::size_t>& candidates_;
    detail::DisjointSets sets_;
    std::vector<double> area_;           // cells
    std::vector<double> closed_, open_;  // boundary cell edges (RegionBoundary)
    std::vector<bool> removed_;
};

// The smallest set that is too small or mostly open to the unobserved outside (not known to be
// enclosed) and still has a door to another set; -1 when none.
int smallestToMerge(RegionMerge& m, double minCells, double maxOpen) {
    int smallest = -1;
    double smallestArea = 0;
    for (std::size_t k = 0; k < m.size(); ++k) {
        const auto [a, b] = m.liveSides(k);
        if (m.removed(k) || a == b)
            continue;
        for (int r : {a, b}) {
            if (m.area(r) > minCells && !m.mostlyOpen(r, maxOpen))
                continue;
            if (smallest < 0 || m.area(r) <= smallestArea) {
                smallest = r;
                smallestArea = m.area(r);
            }
        }
    }
    return smallest;
}

// The widest door of set `smallest` (of two cuts through one doorway the waist stays; a sliver
// between a doorway's cut and a cut along a wall face keeps the doorway's), ties (half a cell):
// the door to its smallest neighbour.
std::size_t widestDoor(RegionMerge& m, int smallest, const std::vector<VirtualDoor>& doors,
                       const std::vector<std::size_t>& candidates) {
    std::size_t through = 0;
    double worstFit = -1, neighbourArea = 1e300;
    for (std::size_t k = 0; k < m.size(); ++k) {
        const auto [a, b] = m.liveSides(k);
        if (m.removed(k) || a == b || (a != smallest && b != smallest))
            continue;
        const double fit = doors[candidates[k]].width;
        const double other = m.area(a == smallest ? b : a);
        if (fit > worstFit + 0.5 || (std::abs(fit - worstFit) <= 0.5 && other < neighbourArea)) {
            worstFit = fit;
            neighbourArea = other;
            through = k;
        }
    }
    return through;
}

}  // namespace

DoorFilters::Rooms DoorFilters::minimumArea(const RegionPartition& partition,
                                            const std::vector<VirtualDoor>& doors,
                                            const std::vector<std::size_t>& candidates,
                                            double cellArea, const RegionBoundary* boundary) const {
    const double minCells = detail::toCells(options_.minRoomArea, cellArea);
    const double maxOpen = options_.maxOpenBoundary;
    RegionMerge merge(partition, candidates, boundary);
    if (!options_.mergeSmallestFirst) {  // the paper: one pass over all doors
        auto fails = [&](int region) {
            return merge.area(region) <= minCells || merge.mostlyOpen(region, maxOpen);
        };
        std::vector<std::size_t> failing;
        for (std::size_t k = 0; k < candidates.size(); ++k) {
            if (fails(merge.sideA(k)) || fails(merge.sideB(k)))
                failing.push_back(k);
        }
        for (std::size_t k : failing)
            merge.removeDoor(k);
    } else {
        // The smallest region to merge is merged through its widest door, again and again.
        for (int smallest = smallestToMerge(merge, minCells, maxOpen); smallest >= 0;
             smallest = smallestToMerge(merge, minCells, maxOpen)) {
            merge.removeDoor(widestDoor(merge, smallest, doors, candidates));
        }
    }
    // A door separates exactly two rooms: one that still touches three or more (crossing cuts)
    // is removed as well, until none is left, so that every two rooms that touch share a door.
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t k = 0; k < candidates.size(); ++k) {
            if (!merge.removed(k) && merge.touchesMoreThanTwo(k)) {
                merge.removeDoor(k);
                changed = true;
            }
        }
    }
    return merge.rooms();
}

}  // namespace toposlam::rooms
