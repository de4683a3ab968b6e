#pragma once
// A building floor plan as vector geometry (world frame, metres): axis-aligned walls with door
// openings, rooms, furniture. It is the ground truth of everything simulated on it: it
// rasterises to an occupancy grid, gives a room label for every place, lists the doors (where
// they are, how wide, which rooms they join), and converts to an exact PolygonWorld.
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPoint2D.h>
#include <toposlam/simulation/PolygonWorld.h>

#include <cstdint>
#include <string>
#include <vector>

namespace toposlam::simulation {

/// Axis-aligned rectangle, m.
struct Box {
    double xMin = 0, yMin = 0, xMax = 0, yMax = 0;
    bool contains(const mrpt::math::TPoint2D& p) const {
        return p.x >= xMin && p.x <= xMax && p.y >= yMin && p.y <= yMax;
    }
    double area() const { return (xMax - xMin) * (yMax - yMin); }
};

struct FloorRoom {
    int id = 0;        ///< 1, 2, ... (0 means "no room" in label images)
    std::string name;  ///< e.g. "office N1"
    std::string kind;  ///< "corridor", "office", "meeting", "kitchen", ...
    Box floor;         ///< the floor between the wall faces
};

struct FloorDoor {
    int id = 0;                         ///< 1, 2, ...
    mrpt::math::TPoint2D jambA, jambB;  ///< ends of the opening on the wall's centre line, m
    double width = 0;                   ///< m, |jambB - jambA|
    int roomA = 0, roomB = 0;           ///< the rooms it joins (FloorRoom::id)
};

class FloorPlan {
  public:
    /// A wall of `thickness` (m) centred on the axis-aligned segment a-b, extending half its
    /// thickness past both ends (so walls meeting at a corner close it).
    void addWall(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b, double thickness);
    /// Returns the new room's id.
    int addRoom(const std::string& name, const std::string& kind, const Box& floor);
    /// An opening from jambA to jambB (on a wall's centre line) joining two rooms; it cuts
    /// through every wall it lies on. Returns the door's id.
    int addDoor(const mrpt::math::TPoint2D& jambA, const mrpt::math::TPoint2D& jambB, int roomA,
                int roomB);
    void addFurniture(const Box& box);
    void addFurniture(const Disc& disc);

    const std::vector<FloorRoom>& rooms() const { return rooms_; }
    const std::vector<FloorDoor>& doors() const { return doors_; }
    const std::vector<Box>& furnitureBoxes() const { return furnitureBoxes_; }
    const std::vector<Disc>& furnitureDiscs() const { return furnitureDiscs_; }
    /// The solid pieces of every wall once the door openings are cut out.
    std::vector<Box> wallPieces() const;
    /// Bounding box of every wall.
    Box extent() const;

    /// Whether `p` is inside a wall piece or a piece of furniture.
    bool isSolid(const mrpt::math::TPoint2D& p) const;
    /// The room whose floor contains `p` (0 if none: inside walls, doorways, outside).
    int roomAt(const mrpt::math::TPoint2D& p) const;

    /// Occupancy grid of the plan at `resolution` (m) with `margin` (m) around extent(): cells
    /// whose centre is solid are occupied, on a room floor or in a doorway free, others unknown.
    mrpt::maps::COccupancyGridMap2D rasterise(double resolution, double margin) const;
    /// Room label of every cell of `grid` (row-major, cy = 0 first; see GridGeometry): the
    /// roomAt() of the cell centre. Furniture stands in rooms, so its cells carry the room's id.
    std::vector<std::uint8_t> roomLabels(const mrpt::maps::COccupancyGridMap2D& grid) const;
    /// Exact vector world of walls and furniture (for ground-truth corners and segments).
    PolygonWorld toPolygonWorld() const;
    /// Rooms and doors as JSON (format in share/doc/file-formats.md, "Office floor plan").
    std::string toJson(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& mapFile,
                       const std::string& labelFile) const;

  private:
    void refreshOpenings();

    struct Wall {
        Box box;
        bool horizontal;
    };
    std::vector<Wall> walls_;
    std::vector<FloorRoom> rooms_;
    std::vector<FloorDoor> doors_;
    std::vector<Box> doorOpenings_;  ///< per door: the opening swept through its wall(s)
    std::vector<Box> furnitureBoxes_;
    std::vector<Disc> furnitureDiscs_;
    double maxWallThickness_ = 0;
};

}  // namespace toposlam::simulation
