#pragma once
// One room-to-room planning job as toposlam-plan runs it: an occupancy grid file and the
// topological map segmented from it (rooms.json or rooms.graphml), start and goal as a user
// names them, the robot and planner settings; out come the path, a description for people and
// the files path.txt and path.png.
#include <toposlam/planning/OmplPathPlanner.h>
#include <toposlam/planning/RoomPath.h>
#include <toposlam/rooms/TopologicalMap.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace toposlam::planning {

struct RoomPlanRequest {
    std::string gridFile;   ///< any format io::loadGridMap reads
    std::string roomsFile;  ///< rooms.json or rooms.graphml (toposlam-rooms)
    /// Start: a room id ("3"), a room name (any case, "kitchen") or a world point "x,y" (m).
    std::string from;
    /// Goal: like `from`, or "farthest": the room whose anchor is farthest from the start.
    std::string to;
    double robotRadius = 0.25;   ///< m: clearance kept from obstacles
    double freeThreshold = 0.6;  ///< cells with p(free) above it are free
    OmplPlannerOptions ompl;
    /// Seed of OMPL's random sampling (same inputs and seed = same path). OMPL takes one seed
    /// per process, before its first sample: give it to the first planRoomToRoom() only.
    std::optional<unsigned> seed;
};

/// `from` or `to` names no room of the map, or is not a point: a mistake of the caller's.
class EndpointError : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};

/// A place a path starts or ends at: a room (its anchor), or a world point.
struct Endpoint {
    std::optional<int> room;
    mrpt::math::TPoint2D point;  ///< m, world frame
};

/// Reads "3", "kitchen" or "4.5,2" (see RoomPlanRequest::from); throws EndpointError naming
/// `option` (e.g. "--from") when the text is none of these.
Endpoint resolveEndpoint(const std::string& text, const rooms::TopologicalMap& map,
                         const std::string& option);
/// The room whose anchor is farthest (straight line) from `p`; throws EndpointError when the
/// map has no room.
Endpoint farthestRoom(const rooms::TopologicalMap& map, const mrpt::math::TPoint2D& p);

/// Throws io::InputError naming `roomsFile` unless `map` can be planned on over `grid`: it has
/// a label image (a GraphML file from another writer may not) of the grid's size.
void checkRoomsFitGrid(const rooms::TopologicalMap& map,
                       const mrpt::maps::COccupancyGridMap2D& grid, const std::string& roomsFile,
                       const std::string& gridFile);

struct RoomPlan {
    rooms::TopologicalMap map;
    RoomPath path;  ///< path.solved false: path.failure says why (no path exists)
    std::string planner;
};

/// Checks the settings (std::invalid_argument), loads both files (io::InputError for bad ones),
/// checks they belong together, resolves the endpoints (EndpointError) and plans.
RoomPlan planRoomToRoom(const RoomPlanRequest& request);

/// "route: room 1 (corridor) -> door 3 -> room 2\nlength: 12.34 m, 56 points, planned in
/// 7.8 ms (rrtconnect)\n" for a solved plan.
std::string describeRoomPlan(const RoomPlan& plan);

/// The names of the files saveRoomPlan writes: path.txt, path.png.
std::vector<std::string> roomPlanFileNames();

/// Writes path.txt (RoomPath.h) and path.png (PathRendering.h) into `folder` (created);
/// returns the two paths.
std::vector<std::string> saveRoomPlan(const RoomPlan& plan, const std::string& folder);

}  // namespace toposlam::planning
