#pragma once
// The topological map of a floor: rooms are the nodes, doors the edges. Rooms keep their cells
// as a label image over the occupancy grid they came from, so a world point can be looked up.
// World frame and units: those of the source grid (m, m^2); images follow GridImageFrame.
#include <toposlam/rooms/GridImageFrame.h>

#include <mrpt/math/TPoint2D.h>

#include <opencv2/core/mat.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace toposlam::rooms {

struct Room {
    int id = 0;        ///< 1..rooms.size(); the value of its cells in the label image
    std::string name;  ///< optional, user-given ("kitchen"); empty when unnamed
    double area = 0;   ///< m^2 (cells x cell area)
    mrpt::math::TPoint2D
        centroid;  ///< mean of its cell centres, m (may lie outside a non-convex room)
    /// The room cell farthest from any obstacle, m: a point well inside the room, e.g. a
    /// navigation goal for "go to room id".
    mrpt::math::TPoint2D anchor;
    /// Outer boundary, m, counter-clockwise in the world frame, along the borders of its cells
    /// (pixel centres of the outermost cells).
    std::vector<mrpt::math::TPoint2D> outline;
};

struct Door {
    int id = 0;                  ///< 1..doors.size()
    mrpt::math::TPoint2D jambA;  ///< centre of the first jamb cell, m
    mrpt::math::TPoint2D jambB;  ///< centre of the other jamb cell, m
    double width = 0;            ///< |jambA - jambB|, m
    int roomA = 0;               ///< the two rooms it joins (roomA < roomB)
    int roomB = 0;
    mrpt::math::TPoint2D middle() const {
        return {0.5 * (jambA.x + jambB.x), 0.5 * (jambA.y + jambB.y)};
    }
};

class TopologicalMap {
  public:
    GridImageFrame frame;
    /// CV_32S, frame.rows x frame.cols: room id per cell, 0 = no room (not free, or free but
    /// unreachable from the largest free region).
    cv::Mat labels;
    std::vector<Room> rooms;  ///< rooms[i].id == i + 1
    std::vector<Door> doors;  ///< doors[i].id == i + 1

    /// A map whose rooms are the labels 1..N of `labels` (CV_32S, 0 = no room, every id in 1..N
    /// used; the map shares the image's data): area, centroid, anchor and outline are computed
    /// from the cells. No doors. `clearance` (optional, CV_32F, same size): each cell's
    /// distance to the nearest obstacle in pixels, computed from labels > 0 when not given.
    static TopologicalMap fromLabels(const GridImageFrame& frame, const cv::Mat& labels,
                                     const cv::Mat& clearance = cv::Mat());

    /// nullptr when there is no room with that id.
    const Room* room(int id) const;
    Room* room(int id);
    /// The room at world point (x, y) (m), 0 when none.
    int roomAt(double x, double y) const;
    /// Room pairs joined by at least one door, each once, (a, b) with a < b, sorted.
    std::vector<std::pair<int, int>> adjacency() const;
    /// Rooms joined to `id` by a door, sorted, each once.
    std::vector<int> neighbours(int id) const;
    /// Doors between rooms a and b (either order).
    std::vector<const Door*> doorsBetween(int a, int b) const;
};

}  // namespace toposlam::rooms
