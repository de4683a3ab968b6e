#pragma once
// Pictures of room segmentations: a topological map as a PNG (rooms coloured, doors drawn as
// lines between their jambs, room ids written at the room anchors, door ids beside the doors),
// and B4's debugging view of a label image with its true and virtual doors.
#include <toposlam/rooms/RoomSegmenter.h>
#include <toposlam/rooms/SegmentationMetrics.h>
#include <toposlam/rooms/TopologicalMap.h>

#include <opencv2/core/mat.hpp>

#include <string>
#include <vector>

namespace toposlam::rooms {

struct RenderOptions {
    int scale = 2;         ///< output pixels per grid cell (1..8)
    bool roomIds = true;   ///< write room ids (and names, when set)
    bool doorIds = false;  ///< write door ids
};

/// BGR image of `map`, top row = largest y (as the map image). Obstacles and unknown space are
/// dark, free cells without a room light grey.
cv::Mat renderTopologicalMap(const TopologicalMap& map, const RenderOptions& options = {});

/// Writes renderTopologicalMap() as a PNG, atomically. Throws std::runtime_error when the file
/// cannot be written.
void saveTopologicalMapPng(const TopologicalMap& map, const std::string& path,
                           const RenderOptions& options = {});

/// B4's view of a label image (CV_32S, 0 = obstacle, 65280 = unassigned free): segments
/// coloured; pixels of the true doors blue; each virtual door's representative point as a
/// circle of the 0.5 m matching radius, green when it matches a true door, red otherwise.
cv::Mat renderLabelImage(const cv::Mat& labels, const cv::Mat& free,
                         const std::vector<LabelBoundaryDoor>& trueDoors,
                         const std::vector<LabelBoundaryDoor>& virtualDoors);

/// What the virtual-door pipeline saw, over the free space `free` (CV_8U, non-zero = free) of
/// the segmented map: wall segments (blue), search-path cells (grey), candidate doors (yellow),
/// candidates that passed the wall-jamb and constriction tests (orange), doors left by the
/// distance filter (magenta) and the final doors (red, thick).
cv::Mat renderDiagnostics(const RoomSegmenter::Result& result, const cv::Mat& free);

/// A distinct, stable colour (BGR) for label `id` > 0.
cv::Vec3b labelColour(int id);

}  // namespace toposlam::rooms
