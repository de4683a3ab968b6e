#pragma once
// A picture of a planned path over its topological map: rooms coloured (as rooms renders
// them), the path in red, the doors of its route highlighted, start and goal marked.
#include <toposlam/planning/RoomPath.h>
#include <toposlam/rooms/TopologicalMap.h>

#include <opencv2/core/mat.hpp>
#include <string>

namespace toposlam::planning {

/// BGR image, `scale` pixels per grid cell, top row = largest y.
cv::Mat renderRoomPath(const rooms::TopologicalMap& map, const RoomPath& path, int scale = 2);
/// Writes renderRoomPath() as a PNG, atomically.
void saveRoomPathPng(const rooms::TopologicalMap& map, const RoomPath& path,
                     const std::string& file, int scale = 2);

}  // namespace toposlam::planning
