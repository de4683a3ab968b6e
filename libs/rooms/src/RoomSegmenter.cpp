#include <toposlam/rooms/DoorSearchPaths.h>
#include <toposlam/rooms/FurniturePockets.h>
#include <toposlam/rooms/RegionPartition.h>
#include <toposlam/rooms/RoomSegmenter.h>

#include "RoomLabelling.h"

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <opencv2/core.hpp>

#include <algorithm>
#include <chrono>

namespace toposlam::rooms {

namespace {

// The parts of `runs` inside `roi`, in its coordinates.
void clipRuns(const std::vector<ConnectedRuns::Run>& runs, const cv::Rect& roi,
              std::vector<ConnectedRuns::Run>& out) {
    out.clear();
    for (const ConnectedRuns::Run& run : runs) {
        const int begin = std::max(run.begin, roi.x), end = std::min(run.end, roi.br().x);
        if (run.row >= roi.y && run.row < roi.br().y && begin < end)
            out.push_back({run.row - roi.y, begin - roi.x, end - roi.x, run.label});
    }
}

// The free region's bounding box plus one ring of background: all later steps work there.
FreeSpace cropToBounds(const FreeSpace& space, cv::Rect& roi) {
    roi = (space.bounds + cv::Size(2, 2) - cv::Point(1, 1)) &
          cv::Rect(0, 0, space.free.cols, space.free.rows);
    FreeSpace out;
    out.free = space.free(roi);
    out.otherFree = space.otherFree.empty() ? cv::Mat() : space.otherFree(roi);
    out.obstacles = space.obstacles.empty() ? cv::Mat() : space.obstacles(roi);
    out.noWall = space.noWall.empty() ? cv::Mat() : space.noWall(roi);
    out.unknown = space.unknown.empty() ? cv::Mat() : space.unknown(roi);
    out.wallHoleReach = space.wallHoleReach;
    out.obstacleOnBorder = space.obstacleOnBorder;
    // Islands inside a smaller free region, and smaller free regions, may lie beyond the crop,
    // or across its edge.
    clipRuns(space.islandRuns, roi, out.islandRuns);
    clipRuns(space.otherFreeRuns, roi, out.otherFreeRuns);
    out.specksRemoved = space.specksRemoved;
    out.unseenHolesFreed = space.unseenHolesFreed;
    out.unseenHoleCells = space.unseenHoleCells;
    out.bounds = space.bounds - roi.tl();
    out.freeCells = space.freeCells;
    out.frame = space.frame;
    out.frame.cols = roi.width;
    out.frame.rows = roi.height;
    out.frame.xMin += roi.x * space.frame.resolution;
    out.frame.yMin += (space.frame.rows - roi.y - roi.height) * space.frame.resolution;
    return out;
}

// The diagnostics of `result`, found on the cropped frame, in full-frame pixels.
void toFullFrame(RoomSegmenter::Result& result, const cv::Rect& roi) {
    auto shift = [&](std::vector<VirtualDoor>& doors) {
        for (VirtualDoor& d : doors) {
            d.jambA += roi.tl();
            d.jambB += roi.tl();
            d.pathCell += roi.tl();
        }
    };
    shift(result.candidates);
    shift(result.afterTests);
    shift(result.wideOpenings);
    shift(result.afterDistance);
    for (cv::Point& p : result.searchCells)
        p += roi.tl();
    const cv::Point2f offset(static_cast<float>(roi.x), static_cast<float>(roi.y));
    for (LineSegment& l : result.lines) {
        l.start += offset;
        l.end += offset;
    }
}

}  // namespace

struct RoomSegmenter::Workspace {
    explicit Workspace(const Options& o)
        : binarizer(o.freeSpace),
          hough(o.hough),
          merger(o.lineMerge),
          voter({o.lineMerge.maxAngleDeg}),
          detector(o.door),
          filters(o.filters),
          wide(o.wide, o.door, o.filters) {}
    FreeSpaceBinarizer binarizer;
    HoughLineExtractor hough;
    LineMerger merger;
    MainDirectionVoter voter;
    VirtualDoorDetector detector;
    DoorFilters filters;
    WideOpeningDetector wide;
    FreeSpace space;
    Clearance clearance;
    WallThickness wallThickness;
    RegionPartition partition;
    RegionBoundary boundary;
    std::vector<cv::Point> sliverCells, sliver;    // otherFree's cells; labelSlivers' scratch
    std::vector<std::pair<int, int>> sliverVotes;  // room, cells: nearestRoomAcrossWall's
    FurniturePockets furniture;
};

RoomSegmenter::RoomSegmenter() : RoomSegmenter(Options{}) {}

RoomSegmenter::RoomSegmenter(const Options& options)
    : options_(options), workspace_(std::make_unique<Workspace>(options_)) {
    options_.validate();
}

RoomSegmenter::~RoomSegmenter() = default;

RoomSegmenter::RoomSegmenter(const RoomSegmenter& other) : RoomSegmenter(other.options_) {}

RoomSegmenter& RoomSegmenter::operator=(const RoomSegmenter& other) {
    if (this != &other) {
        options_ = other.options_;
        workspace_ = std::make_unique<Workspace>(options_);
    }
    return *this;
}

RoomSegmenter::Result RoomSegmenter::segment(const mrpt::maps::COccupancyGridMap2D& grid,
                                             const std::vector<mrpt::math::TPose2D>& trajectory,
                                             const std::string& sourceName) const {
    const auto start = std::chrono::steady_clock::now();
    workspace_->binarizer.binarize(grid, workspace_->space, sourceName);
    const double binarize =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    Result result = segment(workspace_->space, trajectory);
    result.stageMilliseconds.insert(result.stageMilliseconds.begin(), {"binarize", binarize});
    result.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

DoorFilters::Rooms RoomSegmenter::findRooms(const FreeSpace& space,
                                            const std::vector<mrpt::math::TPose2D>& trajectory,
                                            Result& result, const Lap& lap) const {
    Workspace& ws = *workspace_;
    const double res = space.frame.resolution;
    const auto& door = options_.door;

    // Steps 2-3: wall segments and the main directions.
    result.lines = ws.merger.merge(ws.hough.extract(space), res);
    result.directions = ws.voter.vote(result.lines);
    lap("lines+directions");

    // Step 4: virtual doors along the main directions from the search paths.
    result.fromTrajectory = !trajectory.empty();
    ws.clearance.compute(space.free);
    lap("clearance");
    const bool measureWalls = options_.filters.wallThicknessFromMap &&
                              options_.filters.requireWallJambs &&
                              (options_.filters.requireWallEnd || options_.wide.enabled);
    if (measureWalls)
        ws.wallThickness.measure(space, ws.clearance, options_.filters.maxWallThickness);
    const WallThickness* walls = measureWalls ? &ws.wallThickness : nullptr;
    lap("wall thickness");
    const bool medialAxis = !result.fromTrajectory || options_.medialAxisWithTrajectory;
    if (result.fromTrajectory)
        result.searchCells = DoorSearchPaths::fromTrajectory(space, trajectory);
    result.trajectoryCells = result.searchCells.size();
    // The medial axes of the doors and of the wide openings, in one pass.
    std::vector<std::pair<double, double>> widths = {
        {door.doorWidth - door.doorWidthTolerance, door.doorWidth + door.doorWidthTolerance}};
    if (medialAxis && ws.wide.searches())
        widths.push_back(ws.wide.axisWidths());
    const std::vector<std::vector<cv::Point>> axes =
        medialAxis ? DoorSearchPaths::fromMedialAxis(space, ws.clearance, widths)
                   : std::vector<std::vector<cv::Point>>{};
    if (medialAxis)
        result.searchCells.insert(result.searchCells.end(), axes[0].begin(), axes[0].end());
    const std::vector<double> localDirections =
        door.localDirection ? ws.clearance.acrossRidge(result.searchCells) : std::vector<double>{};
    lap("search paths");
    const std::vector<double> directions = {result.directions.phi1, result.directions.phi2};
    result.candidates = ws.detector.detect(space, result.searchCells, directions, localDirections);
    lap("door search");

    // Step 5: filters.
    result.afterTests = ws.filters.constriction(
        space, ws.filters.wallJambs(space, result.candidates, result.lines, walls), door.doorWidth);
    lap("door tests");
    const std::vector<cv::Point> noPath;  // the wide pass searches its own medial axis
    result.wideOpenings =
        ws.wide.detect(space, ws.clearance, medialAxis ? noPath : result.searchCells, directions,
                       result.lines, walls, axes.size() > 1 ? &axes[1] : nullptr);
    result.afterTests.insert(result.afterTests.end(), result.wideOpenings.begin(),
                             result.wideOpenings.end());
    lap("wide openings");
    result.afterDistance = ws.filters.distance(space, result.afterTests);
    lap("distance filter");
    ws.partition.compute(space.free, result.afterDistance);
    const std::vector<std::size_t> adjacent = DoorFilters::adjacency(ws.partition);
    result.afterAdjacency = adjacent.size();
    const bool openRule = options_.filters.maxOpenBoundary < 1;
    if (openRule)
        ws.boundary.measure(space, ws.partition);
    const DoorFilters::Rooms rooms =
        ws.filters.minimumArea(ws.partition, result.afterDistance, adjacent, space.frame.cellArea(),
                               openRule ? &ws.boundary : nullptr);
    lap("partition+filters");
    return rooms;
}

RoomSegmenter::Result RoomSegmenter::segment(
    const FreeSpace& fullSpace, const std::vector<mrpt::math::TPose2D>& trajectory) const {
    const auto start = std::chrono::steady_clock::now();
    Workspace& ws = *workspace_;
    Result result;
    auto last = start;
    const Lap lap = [&](const char* stage) {
        const auto now = std::chrono::steady_clock::now();
        result.stageMilliseconds.emplace_back(
            stage, std::chrono::duration<double, std::milli>(now - last).count());
        last = now;
    };
    cv::Rect roi;
    const FreeSpace space = cropToBounds(fullSpace, roi);
    result.specksRemoved = space.specksRemoved;
    result.unseenHolesFreed = space.unseenHolesFreed;
    result.unseenHoleArea = static_cast<double>(space.unseenHoleCells) * space.frame.cellArea();
    const DoorFilters::Rooms rooms = findRooms(space, trajectory, result, lap);

    // Step 6: the rooms. Region labels become room ids in place; cut cells join a neighbour.
    cv::Mat& labels = ws.partition.mutableLabels();
    detail::labelRooms(space.free, ws.partition, rooms.roomOfRegion, labels);
    if (options_.labelIslands)
        detail::labelIslands(space, labels);
    const bool slivers = options_.maxSliverArea > 0 && !space.otherFree.empty();
    const auto maxSliverCells =
        static_cast<std::size_t>(options_.maxSliverArea / space.frame.cellArea());
    if (slivers) {
        ws.sliverCells.clear();  // empty when there is no pocket
        for (const ConnectedRuns::Run& run : space.otherFreeRuns) {
            for (int x = run.begin; x < run.end; ++x)
                ws.sliverCells.emplace_back(x, run.row);
        }
        detail::labelSlivers(space.otherFree, ws.sliverCells, maxSliverCells, 0, labels, ws.sliver,
                             ws.sliverVotes);
    }
    if (options_.maxFurnitureSize > 0) {
        // A line bounding a room's box holds at least the narrowest door's width of the room;
        // cells within half the thickest wall beyond a door's half width do not count.
        const FurniturePockets::Options pockets{
            options_.maxFurnitureSize, options_.door.doorWidth - options_.door.doorWidthTolerance,
            0.5 * options_.filters.maxWallThickness};
        ws.furniture.label(pockets, result.directions.phi1, result.afterDistance,
                           space.frame.resolution, labels);
    }
    if (slivers) {
        // Once more, now that furniture has its room (a gap behind a desk touches the desk),
        // and across walls: the pockets inside a wall join the nearest room.
        detail::labelSlivers(
            space.otherFree, ws.sliverCells, maxSliverCells,
            static_cast<int>(0.5 * options_.filters.maxWallThickness / space.frame.resolution),
            labels, ws.sliver, ws.sliverVotes);
    }
    lap("labels");
    // Room geometry on the cropped frame (world coordinates do not depend on the crop), then the
    // labels are put back on the full frame.
    result.map = TopologicalMap::fromLabels(space.frame, labels, ws.clearance.distances());
    result.map.frame = fullSpace.frame;
    cv::Mat fullLabels;  // a new image: the map must not share the workspace's labels
    cv::copyMakeBorder(labels, fullLabels, roi.y, fullSpace.frame.rows - roi.br().y, roi.x,
                       fullSpace.frame.cols - roi.br().x, cv::BORDER_CONSTANT, cv::Scalar(0));
    result.map.labels = fullLabels;
    for (const DoorFilters::Rooms::Link& link : rooms.doors) {
        const VirtualDoor& d = result.afterDistance[link.door];
        Door out;
        out.id = static_cast<int>(result.map.doors.size()) + 1;
        out.jambA = space.frame.toWorld(cv::Point2f(d.jambA));
        out.jambB = space.frame.toWorld(cv::Point2f(d.jambB));
        out.width = d.width * space.frame.resolution;
        out.roomA = link.roomA;
        out.roomB = link.roomB;
        result.map.doors.push_back(out);
    }
    lap("room geometry");
    toFullFrame(result, roi);
    result.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace toposlam::rooms
