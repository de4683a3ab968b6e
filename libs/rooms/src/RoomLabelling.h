#pragma once
// Step 6 of the virtual-door segmentation: the partition's regions become rooms, and the cells
// no region holds are given the room they belong to (internal to libs/rooms; RoomSegmenter calls
// them in this order). Every function works in place on a CV_32S label image on the cropped
// frame: room ids > 0, 0 = no room.
#include <toposlam/rooms/FreeSpaceBinarizer.h>
#include <toposlam/rooms/RegionPartition.h>

#include <opencv2/core/mat.hpp>

#include <cstddef>
#include <utility>
#include <vector>

namespace toposlam::rooms::detail {

/// The partition's regions become room ids (`roomOfRegion`) in `labels` (the partition's own
/// label image, taken over: the cuts and the non-free cells stay 0), and the free cells of the
/// door cuts take the label of the nearest labelled cell: 4-connected breadth-first growth,
/// never leaving `free` (CV_8U, 255 = free).
void labelRooms(const cv::Mat& free, const RegionPartition& partition,
                const std::vector<int>& roomOfRegion, cv::Mat& labels);

/// Non-free islands of `space` (obstacles that do not reach the map's edge: furniture, a
/// pillar) take the room around them when all their free 4-neighbours are in that one room; an
/// island between two rooms (a free-standing partition) stays unlabelled: it is a border.
void labelIslands(const FreeSpace& space, cv::Mat& labels);

/// Free pockets outside the segmented free space (`otherFree`, CV_8U: no 4-connected way in) of
/// at most `maxCells` cells take the one room their 8-neighbours hold; with `wallReach` > 0
/// (cells), a pocket inside a wall (no room among its 8-neighbours) takes the nearest room
/// within that reach. `cells`: the cells of `otherFree` in raster order (cv::findNonZero), found
/// once by the caller for both calls. `pocket` and `votes` are scratch, kept by the caller so
/// that repeated calls allocate nothing.
void labelSlivers(const cv::Mat& otherFree, const std::vector<cv::Point>& cells,
                  std::size_t maxCells, int wallReach, cv::Mat& labels,
                  std::vector<cv::Point>& pocket, std::vector<std::pair<int, int>>& votes);

}  // namespace toposlam::rooms::detail
