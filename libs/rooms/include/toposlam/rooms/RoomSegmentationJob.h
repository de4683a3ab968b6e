#pragma once
// What toposlam-rooms does, as a library: load a grid map file (and the robot's trajectory
// while mapping, when known), segment it into rooms, write the topological map in every format
// the app offers and describe it in a few lines of text.
#include <toposlam/io/GridMapIO.h>
#include <toposlam/rooms/RoomSegmenter.h>

#include <optional>
#include <string>
#include <vector>

namespace toposlam::rooms {

struct RoomSegmentationJob {
    std::string mapPath;  ///< any grid map io::loadGridMap reads
    /// Resolution / origin of a bare image (io::loadGridMap); nullopt: its sidecar or defaults.
    std::optional<io::GridMapGeometry> geometry;
    /// 'timestamp x y yaw' lines (s, m, m, rad, map frame); empty: none, the medial axis is
    /// searched instead.
    std::string trajectoryPath;
    RoomSegmenter::Options options;
};

/// Loads the map (and trajectory) and segments it. Throws io::InputError for unreadable files,
/// a trajectory without poses, or one none of whose poses lies in the map's free space (wrong
/// frame or wrong file).
RoomSegmenter::Result runRoomSegmentationJob(const RoomSegmentationJob& job);

/// The names of the files writeRoomSegmentationFiles writes, in that order (an app checks
/// them against its inputs before it starts).
std::vector<std::string> roomSegmentationFileNames();

/// Writes into `dir` (created if needed), each file atomically: rooms.json, rooms.graphml,
/// rooms.png (rooms coloured, doors with ids, `scale` pixels per cell, 1-8), rooms-steps.png
/// (what each step found) and rooms.topomap.gz (CTopologicalMap in an MRPT archive). Returns
/// the paths written. Throws std::invalid_argument for a scale out of range.
std::vector<std::string> writeRoomSegmentationFiles(const RoomSegmenter::Result& result,
                                                    const std::string& dir, int scale = 2);

/// Rooms (area, centroid, neighbours) and doors (rooms, width, middle), one per line, after a
/// first line with the counts and how the doors were searched.
std::string describeRoomSegmentation(const RoomSegmenter::Result& result,
                                     const std::string& mapName);

}  // namespace toposlam::rooms
