#include <toposlam/rooms/WideOpeningDetector.h>

namespace toposlam::rooms {

namespace {

// Eq. 10's range for the wide openings: [widest door, maxWidth). Eq. 10 leaves both ends of
// the door range out, so the wide range reaches a millimetre below it: an opening exactly as
// wide as the widest door (1.6 m = 32 cells of 5 cm between its jamb cells, a 1.55 m double
// door) would otherwise be neither.
VirtualDoorDetector::Options wideRange(const WideOpeningDetector::Options& o,
                                       VirtualDoorDetector::Options door) {
    constexpr double kOverlap = 1e-3;  // m
    const double lo = door.doorWidth + door.doorWidthTolerance - kOverlap;
    door.doorWidth = 0.5 * (lo + o.maxWidth);
    door.doorWidthTolerance = 0.5 * (o.maxWidth - lo);
    door.localDirection = door.localDirection && o.localDirection;
    return door;
}

// Step 5's tests, stricter: wall ends on both sides, constriction by the wide margin.
DoorFilters::Options wideTests(const WideOpeningDetector::Options& o,
                               DoorFilters::Options filters) {
    filters.requireWallJambs = true;
    filters.requireWallEnd = true;
    filters.requireBothWallEnds = true;
    filters.requireConstriction = true;
    filters.openingMargin = o.openingMargin;
    return filters;
}

}  // namespace

WideOpeningDetector::WideOpeningDetector(const Options& options,
                                         const VirtualDoorDetector::Options& door,
                                         const DoorFilters::Options& filters)
    : options_(options),
      minWidth_(door.doorWidth + door.doorWidthTolerance),
      axisMinWidth_(door.doorWidth),
      detector_(wideRange(options, door)),
      filters_(wideTests(options, filters)) {}

std::vector<VirtualDoor> WideOpeningDetector::detect(
    const FreeSpace& space, const Clearance& clearance, const std::vector<cv::Point>& pathCells,
    const std::vector<double>& directions, const std::vector<LineSegment>& walls,
    const WallThickness* thickness, const std::vector<cv::Point>* medialAxis) const {
    if (!searches())
        return {};
    std::vector<cv::Point> ownAxis;
    if (pathCells.empty() && medialAxis == nullptr)
        ownAxis =
            DoorSearchPaths::fromMedialAxis(space, clearance, axisMinWidth_, options_.maxWidth);
    const std::vector<cv::Point>& cells =
        !pathCells.empty() ? pathCells : (medialAxis != nullptr ? *medialAxis : ownAxis);
    const std::vector<double> local =
        detector_.options().localDirection ? clearance.acrossRidge(cells) : std::vector<double>{};
    std::vector<VirtualDoor> openings = detector_.detect(space, cells, directions, local);
    return filters_.constriction(
        space, filters_.wallJambs(space, std::move(openings), walls, thickness), options_.maxWidth);
}

}  // namespace toposlam::rooms
