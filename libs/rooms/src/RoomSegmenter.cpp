#include <toposlam/rooms/DoorSearchPaths.h>
#include <toposlam/rooms/FurniturePockets.h>
#include <toposlam/rooms/RegionPartition.h>
#include <toposlam/rooms/RoomSegmenter.h>

#include "GridRay.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <toposlam/config/IniFile.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <toposlam/io/InputError.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <stdexcept>

namespace toposlam::rooms {

namespace {

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
    out.obstacleOnBorder = space.obstacleOnBorder;
    out.specksRemoved = space.specksRemoved;
    out.bounds = space.bounds - roi.tl();
    out.freeCells = space.freeCells;
    out.frame = space.frame;
    out.frame.cols = roi.width;
    out.frame.rows = roi.height;
    out.frame.xMin += roi.x * space.frame.resolution;
    out.frame.yMin += (space.frame.rows - roi.y - roi.height) * space.frame.resolution;
    return out;
}

// Region labels become room ids in place (`roomOfRegion`; region 0, the cuts and the non-free
// cells, stays 0), and the free cells left unlabelled (the door cuts) get the label of the
// nearest labelled cell: 4-connected breadth-first growth from the labelled cells next to them,
// in raster order, never leaving `free`.
void labelRooms(const cv::Mat& free, const std::vector<int>& roomOfRegion, cv::Mat& labels) {
    const cv::Point around[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    auto inside = [&](const cv::Point& q) {
        return q.x >= 0 && q.y >= 0 && q.x < labels.cols && q.y < labels.rows;
    };
    std::deque<cv::Point> queue;
    for (int r = 0; r < labels.rows; ++r) {
        int* row = labels.ptr<int>(r);
        const auto* f = free.ptr<std::uint8_t>(r);
        for (int c = 0; c < labels.cols; ++c) {
            const int region = row[c];
            row[c] = roomOfRegion[static_cast<std::size_t>(region)];
            if (region != 0 || f[c] == 0)
                continue;
            // An unlabelled free cell: its labelled neighbours seed the growth (a region is
            // labelled when its room is, whether it was renamed yet or not).
            for (const cv::Point& o : around) {
                const cv::Point q(c + o.x, r + o.y);
                if (inside(q) && labels.at<int>(q) != 0)
                    queue.push_back(q);
            }
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

// Gives the cells of every non-free island of `space` (an obstacle that does not reach the
// map's edge: furniture, a pillar) the room around it, when all its free 4-neighbours are in
// that one room (an island between two rooms, such as a free-standing partition, stays
// unlabelled: it is a border).
void labelIslands(const FreeSpace& space, cv::Mat& labels) {
    const cv::Mat& obstacles = space.obstacles;
    std::vector<std::vector<std::pair<int, int>>> votes(space.obstacleOnBorder.size());
    const cv::Point around[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    const cv::Rect image(0, 0, labels.cols, labels.rows);
    for (int r = 0; r < obstacles.rows; ++r) {
        const int* row = obstacles.ptr<int>(r);
        for (int c = 0; c < obstacles.cols; ++c) {
            const auto island = static_cast<std::size_t>(row[c]);
            if (island == 0 || space.obstacleOnBorder[island])
                continue;
            for (const cv::Point& o : around) {
                const cv::Point q(c + o.x, r + o.y);
                const int room = image.contains(q) ? labels.at<int>(q) : 0;
                if (room <= 0)
                    continue;
                auto& v = votes[island];
                auto it = std::find_if(v.begin(), v.end(),
                                       [&](const auto& p) { return p.first == room; });
                if (it == v.end())
                    v.emplace_back(room, 1);
                else
                    ++it->second;
            }
        }
    }
    std::vector<int> roomOf(votes.size(), 0);
    bool any = false;
    for (std::size_t i = 0; i < votes.size(); ++i) {
        if (votes[i].size() == 1) {
            roomOf[i] = votes[i].front().first;
            any = true;
        }
    }
    if (!any)
        return;  // no island inside one room: nothing to relabel
    for (int r = 0; r < obstacles.rows; ++r) {
        const int* row = obstacles.ptr<int>(r);
        int* out = labels.ptr<int>(r);
        for (int c = 0; c < obstacles.cols; ++c) {
            if (row[c] != 0 && roomOf[static_cast<std::size_t>(row[c])] != 0)
                out[c] = roomOf[static_cast<std::size_t>(row[c])];
        }
    }
}

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

// Gives each free pocket outside the segmented free space (`otherFree`: no 4-connected way in)
// of at most `maxCells` cells the room it touches, when its 8-neighbours hold exactly one room.
// Such pockets are mostly drawing artefacts: free cells caught between the steps of a wall
// rasterised at an angle. A pocket whose 8-neighbours hold no room at all lies inside a wall
// (on SLAM grids: cells a few grazing or noisy rays went through) and takes the nearest room
// within `wallReach` cells (0: none), whatever its size if it is a line. Larger pockets, those
// between two rooms, and those reaching the edge of the (cropped) image, which may go on beyond
// it, stay unlabelled. `cells`, `pocket` and `votes` are scratch.
void labelSlivers(const cv::Mat& otherFree, std::size_t maxCells, int wallReach, cv::Mat& labels,
                  std::vector<cv::Point>& cells, std::vector<cv::Point>& pocket,
                  std::vector<std::pair<int, int>>& votes) {
    cv::findNonZero(otherFree, cells);        // empty when there is no pocket
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

}  // namespace

RoomSegmenter::Options RoomSegmenter::Options::paperExact() {
    Options o;
    o.applyPaperPreset();
    return o;
}

void RoomSegmenter::Options::applyPaperPreset() {
    freeSpace.maxSpeckArea = 0;
    freeSpace.occupiedThreshold = 1;  // every non-free cell is a wall
    door.localDirection = false;
    filters.keepNarrowestOfGroup = false;
    filters.mergeSmallestFirst = false;
    filters.requireWallJambs = false;
    filters.requireWallEnd = false;
    filters.requireConstriction = false;
    filters.constrictionAtWaist = false;
    filters.rejectCorridorCuts = false;
    filters.wallEndNotOnAFace = false;
    filters.wallThicknessFromMap = false;
    filters.maxOpenBoundary = 1;
    wide.enabled = false;
    labelIslands = false;
    maxSliverArea = 0;
    maxFurnitureSize = 0;
    medialAxisWithTrajectory = false;
}

RoomSegmenter::Options RoomSegmenter::Options::load(const std::string& iniPath, bool paper) {
    Options o;
    if (!iniPath.empty()) {
        const auto ini = config::openIniFile(iniPath);  // InputError / ConfigError
        config::requireSection(*ini, "RoomSegmenter");
        o.loadFromConfigFile(*ini, "RoomSegmenter");
    }
    if (paper)
        o.applyPaperPreset();
    o.validate();
    return o;
}

void RoomSegmenter::Options::validate() const {
    config::Options::validate("RoomSegmenter");
}

void RoomSegmenter::Options::loadFromConfigFile(const mrpt::config::CConfigFileBase& ini,
                                                const std::string& section) {
    if (config::rawValue(ini, section, "variant") == "paper")
        applyPaperPreset();  // the keys of the section override it
    config::Options::loadFromConfigFile(ini, section);
}

void RoomSegmenter::Options::declare(config::OptionsSchema& s) {
    s.choice("variant", variant, {{"improved", Variant::Improved}, {"paper", Variant::Paper}},
             "improved: the defaults (paper + TopoSLAM's deviations); paper: every deviation "
             "off, before the keys below");
    // Step 1: binarisation.
    s.real("free_threshold", freeSpace.freeThreshold, "", "a cell is free when p(free) > this")
        .atLeast(0)
        .below(1);
    s.real("max_speck_area", freeSpace.maxSpeckArea, "m^2",
           "non-free specks up to this area inside free space count as free (0: paper)")
        .atLeast(0);
    s.real("occupied_threshold", freeSpace.occupiedThreshold, "",
           "a non-free cell is occupied when p(free) < this, else unknown (deviation)")
        .atLeast(0)
        .atMost(1);
    s.real("wall_hole_reach", freeSpace.wallHoleReach, "m",
           "unknown cells this close to an occupied cell are wall, farther ones no wall")
        .atLeast(0);
    // Step 2: wall segments and their merge.
    s.real("hough_angle_resolution_deg", hough.angleResolutionDeg, "deg",
           "Hough accumulator angle step")
        .above(0)
        .atMost(45);
    s.real("hough_min_votes_length", hough.minVotesLength, "m",
           "accumulator threshold as metres of wall voting for a line")
        .above(0);
    s.real("hough_min_line_length", hough.minLineLength, "m", "shortest wall segment kept")
        .above(0);
    s.real("hough_max_line_gap", hough.maxLineGap, "m", "largest gap bridged inside a segment")
        .atLeast(0);
    s.real("merge_max_angle_deg", lineMerge.maxAngleDeg, "deg",
           "delta_phi of the line merge and the main-direction voter")
        .above(0)
        .atMost(45);
    s.real("merge_max_distance", lineMerge.maxDistance, "m", "delta_d of the line merge")
        .atLeast(0);
    // Step 4: virtual doors.
    s.real("door_width", door.doorWidth, "m", "openings of door_width ...").above(0);
    s.real("door_width_tolerance", door.doorWidthTolerance, "m", "... +- this are doors").above(0);
    s.require([this] { return door.doorWidthTolerance < door.doorWidth; }, "door_width_tolerance",
              "must be below door_width");
    s.flag("local_direction", door.localDirection,
           "search doors across the local wall direction too (deviation)");
    // Step 5: filters.
    s.real("frame_distance", filters.frameDistance, "m",
           "doors closer than this to each other are one group")
        .atLeast(0);
    s.real("min_room_area", filters.minRoomArea, "m^2", "smaller regions are merged (N_s)")
        .atLeast(0);
    s.flag("keep_narrowest_of_group", filters.keepNarrowestOfGroup,
           "keep the narrowest door of a group (deviation)");
    s.flag("merge_smallest_first", filters.mergeSmallestFirst,
           "merge the smallest region first (deviation)");
    s.flag("require_wall_jambs", filters.requireWallJambs,
           "both ends of a door must be walls (deviation)");
    s.real("min_wall_extent", filters.minWallExtent, "m", "a jamb's wall extends this far")
        .above(0);
    s.flag("require_wall_end", filters.requireWallEnd,
           "one jamb must be the end of a wall (deviation)");
    s.real("max_wall_thickness", filters.maxWallThickness, "m", "thickest wall end").above(0);
    s.real("wall_end_probe", filters.wallEndProbe, "m", "probe length along the wall").above(0);
    s.real("edge_depth", filters.edgeDepth, "m",
           "a wall end free on one side only is the map's edge when nothing is free this deep "
           "behind it")
        .atLeast(0);
    s.flag(
        "reject_corridor_cuts", filters.rejectCorridorCuts,
        "no door with both jambs on walls going on to one side of it: a corridor's cross-section "
        "(deviation)");
    s.flag("wall_end_not_on_a_face", filters.wallEndNotOnAFace,
           "a jamb on the face of a wall running on to both sides of the door line is no wall end "
           "(deviation)");
    s.flag("wall_thickness_from_map", filters.wallThicknessFromMap,
           "wall ends as thick as the building's walls, measured on the map (deviation)");
    s.flag("require_constriction", filters.requireConstriction,
           "a door must be narrower than the space on both sides (deviation)");
    s.real("opening_margin", filters.openingMargin, "m", "by at least this").atLeast(0);
    s.flag("constriction_at_waist", filters.constrictionAtWaist,
           "a cut is dropped when a narrower cut of the same opening is no constriction "
           "(deviation)");
    s.real("max_open_boundary", filters.maxOpenBoundary, "",
           "a region whose boundary is more than this fraction open to the unobserved outside is "
           "merged (deviation; 1 = off)")
        .atLeast(0)
        .atMost(1);
    // Wide openings (deviation).
    s.flag("wide_openings", wide.enabled, "openings wider than a door may be room borders");
    s.real("max_opening_width", wide.maxWidth, "m", "widest such opening").above(0);
    s.flag("wide_local_direction", wide.localDirection,
           "search wide openings across the clearance ridge too (off: the main directions only)");
    s.real("wide_opening_margin", wide.openingMargin, "m", "the space behind must be wider by this")
        .atLeast(0);
    s.flag("label_islands", labelIslands,
           "free-standing furniture inside a room takes its label (deviation)");
    s.real("max_sliver_area", maxSliverArea, "m^2",
           "free pockets up to this size cut off from the free space join the one room they "
           "touch, or inside a wall the nearest room (deviation; 0 = off)")
        .atLeast(0);
    s.real("max_furniture_size", maxFurnitureSize, "m",
           "non-free pockets along a room's walls up to this long both ways (furniture) join the "
           "room (deviation; 0 = off)")
        .atLeast(0);
    s.flag("medial_axis_with_trajectory", medialAxisWithTrajectory,
           "with a trajectory, search the medial axis too (deviation)");
}

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
    std::vector<cv::Point> sliverCells, sliver;    // labelSlivers' scratch
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
        widths.push_back(ws.wide.widths());
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
    result.afterDistance = ws.filters.distance(result.afterTests, res);
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
    const DoorFilters::Rooms rooms = findRooms(space, trajectory, result, lap);

    // Step 6: the rooms. Region labels become room ids in place; cut cells join a neighbour.
    cv::Mat& labels = ws.partition.mutableLabels();
    labelRooms(space.free, rooms.roomOfRegion, labels);
    if (options_.labelIslands && !space.obstacles.empty())
        labelIslands(space, labels);
    const bool slivers = options_.maxSliverArea > 0 && !space.otherFree.empty();
    const auto maxSliverCells =
        static_cast<std::size_t>(options_.maxSliverArea / space.frame.cellArea());
    if (slivers)
        labelSlivers(space.otherFree, maxSliverCells, 0, labels, ws.sliverCells, ws.sliver,
                     ws.sliverVotes);
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
        labelSlivers(
            space.otherFree, maxSliverCells,
            static_cast<int>(0.5 * options_.filters.maxWallThickness / space.frame.resolution),
            labels, ws.sliverCells, ws.sliver, ws.sliverVotes);
    }
    lap("labels");
    // Room geometry on the cropped frame (world coordinates do not depend on the crop), then the
    // labels are put back on the full frame.
    result.map = TopologicalMap::fromLabels(space.frame, labels, ws.clearance.distances());
    result.map.frame = fullSpace.frame;
    result.map.labels = cv::Mat::zeros(fullSpace.frame.rows, fullSpace.frame.cols, CV_32S);
    labels.copyTo(result.map.labels(roi));
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
