#pragma once
// The room-sized free areas of a map: the places a tour must visit. Doorways are narrow; rooms
// and corridors are wide. So: keep the free cells whose clearance exceeds half the widest
// doorway (equivalently, erode free space by that radius); every doorway closes, and each
// connected region that remains is one room-sized area (a room, a corridor, or the part of a
// room that furniture leaves wide). Its representative point is the centre of the largest
// empty disc inside it (the maximum of the distance transform).
#include <mrpt/math/TPoint2D.h>
#include <toposlam/simulation/ClearanceMap.h>

#include <vector>

namespace toposlam::simulation {

struct RoomSizedAreaOptions {
    /// m; openings up to this wide separate areas (doors are 0.8-1.0 m, double doors more).
    double doorWidthMax = 1.2;
    /// m^2; eroded regions smaller than this are ignored (nooks, noise in SLAM maps).
    double minAreaM2 = 0.25;
};

struct RoomSizedArea {
    mrpt::math::TPoint2D centre;  ///< world frame, m: centre of the largest empty disc
    double clearance = 0;         ///< m, that disc's radius
    double erodedAreaM2 = 0;      ///< m^2 of the eroded region (grows with the room's size)
    /// The region reaches the map's edge: free space the map does not bound, such as the
    /// surroundings of a building drawn on a free background (a room ends at walls).
    bool openToMapEdge = false;
};

/// Areas sorted by decreasing erodedAreaM2.
std::vector<RoomSizedArea> findRoomSizedAreas(const ClearanceMap& map,
                                              const RoomSizedAreaOptions& options = {});

}  // namespace toposlam::simulation
