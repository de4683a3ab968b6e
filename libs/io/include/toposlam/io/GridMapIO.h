#pragma once
// Occupancy grid maps in and out, in every format TopoSLAM reads or writes:
//   .gridmap / .gridmap.gz   MRPT serialization of COccupancyGridMap2D (plain or gzip)
//   .png (also .pgm .bmp .jpg on input)  image: dark = occupied, white = free, mid grey =
//                            unknown; resolution and origin from GridMapGeometry or the
//                            "<stem>.png.yaml"-style sidecar documented in the README
//   .yaml                    ROS map_server metadata (image, resolution, origin, negate,
//                            occupied_thresh, free_thresh) + its PGM/PNG image
// Frames: the map's world frame, metres; the origin is the world position of the lower-left
// corner of the lower-left cell (ROS convention). Occupancy follows MRPT: p(free), 0 =
// occupied, 1 = free, 0.5 = unknown.
#include <mrpt/maps/COccupancyGridMap2D.h>

#include <optional>
#include <string>

namespace toposlam::io {

/// Geometry for image maps that carry none themselves.
struct GridMapGeometry {
    double resolution = 0.05;  ///< m per cell
    double originX = 0.0;      ///< world x (m) of the lower-left corner of the image
    double originY = 0.0;      ///< world y (m) of the lower-left corner of the image
};

/// Loads a grid map, choosing the format from the extension. For images, `geometry` overrides
/// any sidecar; without either, 0.05 m/cell and origin (0,0) are used.
/// Throws InputError for a missing, unreadable or corrupt file.
mrpt::maps::COccupancyGridMap2D loadGridMap(
    const std::string& path, const std::optional<GridMapGeometry>& geometry = std::nullopt);

/// Saves `map`, choosing the format from the extension (.gridmap, .gridmap.gz, .png, .yaml).
/// Atomic: no partial file is left on failure. Image formats also write their metadata
/// (.yaml: the image beside it; .png: the sidecar), so that loadGridMap restores the geometry.
void saveGridMap(const mrpt::maps::COccupancyGridMap2D& map, const std::string& path);

}  // namespace toposlam::io
