#include <toposlam/rooms/VirtualDoorDetector.h>

#include "GridRay.h"

#include <cmath>

namespace toposlam::rooms {

bool VirtualDoorDetector::castRay(const cv::Mat& free, const cv::Point& from, double ux, double uy,
                                  double maxDistance, cv::Point& hit) {
    return detail::walkRay(
        from, ux, uy, maxDistance, [&](int x, int y) { return !detail::isSet(free, x, y); }, hit);
}

std::vector<VirtualDoor> VirtualDoorDetector::detect(
    const FreeSpace& space, const std::vector<cv::Point>& pathCells,
    const std::vector<double>& directions, const std::vector<double>& localDirections) const {
    const double res = space.frame.resolution;
    const double target = detail::toCells(options_.doorWidth, res);
    const double tolerance = detail::toCells(options_.doorWidthTolerance, res);
    // A jamb farther than the widest door cannot belong to a door through this cell.
    const double reach = target + tolerance + 1.0;
    const bool local = options_.localDirection && localDirections.size() == pathCells.size();
    auto crossSection = [&](const cv::Point& p, double direction, int index, VirtualDoor& door) {
        const double ux = std::cos(direction), uy = std::sin(direction);
        cv::Point a, b;
        if (!castRay(space.free, p, ux, uy, reach, a) ||
            !castRay(space.free, p, -ux, -uy, reach, b)) {
            return false;
        }
        const double width = std::hypot(a.x - b.x, a.y - b.y);
        if (std::abs(width - target) >= tolerance)
            return false;  // eq. 10
        door = {a, b, width, index, p};
        return true;
    };
    std::vector<VirtualDoor> doors;
    VirtualDoor found;
    for (std::size_t i = 0; i < pathCells.size(); ++i) {
        const cv::Point& p = pathCells[i];
        if (!local) {  // the paper: the first main direction that gives a door
            for (std::size_t k = 0; k < directions.size(); ++k) {
                if (crossSection(p, directions[k], static_cast<int>(k), found)) {
                    doors.push_back(found);
                    break;
                }
            }
            continue;
        }
        // Every direction that passes eq. 10: a narrower cross-section through an obstacle that
        // is no jamb (a chair, a speck) must not hide the real one; the filters choose.
        for (std::size_t k = 0; k < directions.size(); ++k) {
            if (crossSection(p, directions[k], static_cast<int>(k), found))
                doors.push_back(found);
        }
        if (crossSection(p, localDirections[i], static_cast<int>(directions.size()), found)) {
            doors.push_back(found);
        }
    }
    return doors;
}

}  // namespace toposlam::rooms
