// The constriction test of the door filters (DoorFilters.h): a door is a narrow place between
// two wider spaces, judged at the waist of its opening.
#include <toposlam/rooms/DoorFilters.h>

#include "DoorNeighbours.h"
#include "GridRay.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace toposlam::rooms {

namespace {

// Whether the free space across direction (ux, uy) through the cell `at` is wider than `cap`
// pixels (from the non-free cell on one side to the one on the other; none within cap on a
// side: wider).
bool wider(const cv::Mat& free, const cv::Point& at, double ux, double uy, double cap) {
    cv::Point a, b;
    const bool bounded = detail::withMaskReader(free, at, cap + 1, [&](const auto& isFree) {
        auto blocked = [&](int x, int y) { return !isFree(x, y); };
        // Beyond farSideReach the other side is wider than cap anyway.
        return detail::walkRay(at, ux, uy, cap, blocked, a) &&
               detail::walkRay(at, -ux, -uy,
                               std::min(cap, detail::farSideReach(at, a, ux, uy, cap)), blocked, b);
    });
    return !bounded || detail::cellDistance(a.x - b.x, a.y - b.y) > cap;
}

}  // namespace

std::vector<VirtualDoor> DoorFilters::constriction(const FreeSpace& space,
                                                   std::vector<VirtualDoor> doors,
                                                   double probeDistance) const {
    if (!options_.requireConstriction)
        return doors;
    const double margin = detail::toCells(options_.openingMargin, space.frame.resolution);
    const int steps = std::max(
        1, static_cast<int>(std::ceil(detail::toCells(probeDistance, space.frame.resolution))));
    auto opensOnSide = [&](const VirtualDoor& d, double side) {
        const double ux = (d.jambB.x - d.jambA.x) / d.width;
        const double uy = (d.jambB.y - d.jambA.y) / d.width;
        const cv::Point2d centre = 0.5 * (cv::Point2d(d.jambA) + cv::Point2d(d.jambB));
        const double opened = d.width + margin;
        for (int k = 1; k <= steps; ++k) {
            const cv::Point q(cvRound(centre.x - side * k * uy), cvRound(centre.y + side * k * ux));
            if (!detail::isSet(space.free, q.x, q.y))
                return false;  // a wall before it opened
            if (wider(space.free, q, ux, uy, opened))
                return true;
        }
        return false;
    };
    std::vector<std::uint8_t> opens(doors.size());
    for (std::size_t i = 0; i < doors.size(); ++i)
        opens[i] = opensOnSide(doors[i], 1.0) && opensOnSide(doors[i], -1.0);
    if (options_.constrictionAtWaist) {
        // A cut that opens is dropped when a narrower cut of the same opening (jambs within
        // frameDistance) does not: the opening is judged at its waist. An oblique cut across a
        // corridor is longer than the corridor is wide, and its probes, drifting along the
        // corridor, can reach a side door and find it "wider"; the straight cut does not.
        const double nd = detail::toCells(options_.frameDistance, space.frame.resolution);
        detail::MidpointBuckets closed(nd);
        for (std::size_t j = 0; j < doors.size(); ++j) {
            if (!opens[j])
                closed.add(doors[j], j);
        }
        std::vector<std::uint8_t> keep(opens);
        for (std::size_t i = 0; i < doors.size(); ++i) {
            if (!opens[i])
                continue;
            closed.forNeighbours(doors[i], [&](std::size_t j) {
                if (doors[j].width < doors[i].width - 1.0 &&
                    detail::jambDistance(doors[i], doors[j]) <= nd)
                    keep[i] = 0;
            });
        }
        opens.swap(keep);
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < doors.size(); ++i) {
        if (opens[i])
            doors[kept++] = doors[i];
    }
    doors.resize(kept);
    return doors;
}

}  // namespace toposlam::rooms
