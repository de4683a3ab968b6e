#include <toposlam/rooms/VirtualDoorDetector.h>

#include "GridRay.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

namespace toposlam::rooms {

bool VirtualDoorDetector::castRay(const cv::Mat& free, const cv::Point& from, double ux, double uy,
                                  double maxDistance, cv::Point& hit) {
    return detail::withMaskReader(free, from, maxDistance + 1, [&](const auto& isFree) {
        return detail::walkRay(
            from, ux, uy, maxDistance, [&](int x, int y) { return !isFree(x, y); }, hit);
    });
}

namespace {

// Eq. 10 on the two jamb cells found: the door, or nothing.
bool isDoorWidth(const cv::Point& a, const cv::Point& b, double target, double tolerance,
                 double& width) {
    width = detail::cellDistance(a.x - b.x, a.y - b.y);
    return std::abs(width - target) < tolerance;
}

// Keeps the first of the doors with the same two jamb cells, in order: the path cells along one
// cut line all find it, and the filters would test it again for each (half the candidates on
// Bormann's maps).
void keepEachCutOnce(std::vector<VirtualDoor>& doors) {
    struct Cut {
        cv::Point first, second;  // the jamb cells, in raster order
        std::size_t door;
    };
    std::vector<Cut> cuts(doors.size());
    for (std::size_t i = 0; i < doors.size(); ++i) {
        const VirtualDoor& d = doors[i];
        const bool aFirst = std::tie(d.jambA.y, d.jambA.x) <= std::tie(d.jambB.y, d.jambB.x);
        cuts[i] = {aFirst ? d.jambA : d.jambB, aFirst ? d.jambB : d.jambA, i};
    }
    const auto cell = [](const Cut& c) {
        return std::tie(c.first.y, c.first.x, c.second.y, c.second.x);
    };
    // Stable: within one cut the doors stay in their order, the first comes first.
    std::stable_sort(cuts.begin(), cuts.end(),
                     [&](const Cut& a, const Cut& b) { return cell(a) < cell(b); });
    std::vector<char> keep(doors.size(), 0);
    for (std::size_t k = 0; k < cuts.size(); ++k)
        keep[cuts[k].door] = k == 0 || cell(cuts[k]) != cell(cuts[k - 1]);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < doors.size(); ++i) {
        if (keep[i])
            doors[kept++] = doors[i];
    }
    doors.resize(kept);
}

}  // namespace

std::vector<VirtualDoor> VirtualDoorDetector::detect(
    const FreeSpace& space, const std::vector<cv::Point>& pathCells,
    const std::vector<double>& directions, const std::vector<double>& localDirections) const {
    const double res = space.frame.resolution;
    const double target = detail::toCells(options_.doorWidth, res);
    const double tolerance = detail::toCells(options_.doorWidthTolerance, res);
    // A jamb farther than the widest door cannot belong to a door through this cell.
    const double reach = target + tolerance + 1.0;
    const bool local = options_.localDirection && localDirections.size() == pathCells.size();
    // The main directions are the same from every cell: their rays are walked once (both
    // ways), then only looked up.
    std::vector<detail::RayPattern> ahead, behind;
    std::vector<double> cosines, sines;
    for (const double direction : directions) {
        cosines.push_back(std::cos(direction));
        sines.push_back(std::sin(direction));
        ahead.emplace_back(cosines.back(), sines.back(), reach, space.free);
        behind.emplace_back(-cosines.back(), -sines.back(), reach, space.free);
    }
    // Behind, a jamb is looked for only as far as it could still give a door (eq. 10) with
    // the one found ahead.
    const double widest = target + tolerance;
    auto mainSection = [&](const cv::Point& p, std::size_t k, VirtualDoor& door) {
        cv::Point a, b;
        double width = 0;
        if (!ahead[k].firstUnset(space.free, p, a))
            return false;
        const double back = detail::farSideReach(p, a, cosines[k], sines[k], widest);
        if (!behind[k].firstUnset(space.free, p, std::min(reach, back), b) ||
            !isDoorWidth(a, b, target, tolerance, width)) {
            return false;
        }
        door = {a, b, width, static_cast<int>(k), p};
        return true;
    };
    auto localSection = [&](const cv::Point& p, double direction, VirtualDoor& door) {
        const double ux = std::cos(direction), uy = std::sin(direction);
        cv::Point a, b;
        double width = 0;
        if (!castRay(space.free, p, ux, uy, reach, a))
            return false;
        const double back = detail::farSideReach(p, a, ux, uy, widest);
        if (!castRay(space.free, p, -ux, -uy, std::min(reach, back), b) ||
            !isDoorWidth(a, b, target, tolerance, width)) {
            return false;
        }
        door = {a, b, width, static_cast<int>(directions.size()), p};
        return true;
    };
    std::vector<VirtualDoor> doors;
    VirtualDoor found;
    for (std::size_t i = 0; i < pathCells.size(); ++i) {
        const cv::Point& p = pathCells[i];
        if (!local) {  // the paper: the first main direction that gives a door
            for (std::size_t k = 0; k < directions.size(); ++k) {
                if (mainSection(p, k, found)) {
                    doors.push_back(found);
                    break;
                }
            }
            continue;
        }
        // Every direction that passes eq. 10: a narrower cross-section through an obstacle that
        // is no jamb (a chair, a speck) must not hide the real one; the filters choose.
        for (std::size_t k = 0; k < directions.size(); ++k) {
            if (mainSection(p, k, found))
                doors.push_back(found);
        }
        if (localSection(p, localDirections[i], found))
            doors.push_back(found);
    }
    keepEachCutOnce(doors);
    return doors;
}

}  // namespace toposlam::rooms
