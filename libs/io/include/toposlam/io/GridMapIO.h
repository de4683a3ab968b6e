#pragma once
// Occupancy grid maps in and out, in every format TopoSLAM reads or writes (the format is
// chosen by the file extension, case-insensitive):
//   .gridmap / .gridmap.gz  MRPT serialization of COccupancyGridMap2D (plain or gzip), what
//                           MRPT's own apps read and write. Exact: MRPT's reader rounds the
//                           stored limits to multiples of the resolution, so loadGridMap
//                           restores them from the file; saving refuses the rare maps whose
//                           size MRPT would then misread (use .png or .yaml for those).
//   .yaml (.yml)            ROS map_server: the YAML metadata (image, resolution, origin,
//                           negate, occupied_thresh, free_thresh, mode) plus its image.
//                           Written as map_server's map_saver does: a trinary 8-bit PGM beside
//                           the YAML (occupied 0, free 254, unknown 205).
//   .png                    8-bit grey picture of p(free) (0 black = occupied, 255 white =
//                           free, 128 = unknown, as MRPT draws grids) with its geometry in the
//                           sidecar "<stem>.yaml" next to it: ROS map_server metadata with
//                           "image: <stem>.png" and "mode: scale", so ROS tools load it too.
//   .pgm                    as .yaml (trinary PGM + "<stem>.yaml").
//   .png .pgm .bmp .jpg .jpeg .tif .tiff on input: the sidecar "<stem>.yaml" is used when it
//                           exists and its `image` is this file; otherwise the image is bare:
//                           p(free) = grey / 255 (colour and alpha images are read as grey),
//                           with the geometry given by the caller (default 0.05 m/cell,
//                           origin (0,0)).
// Reading ROS metadata: mode trinary (the default) follows map_server exactly
// (p_occ = (255 - grey)/255, or grey/255 with negate; p_occ > occupied_thresh: occupied,
// p_occ < free_thresh: free, otherwise unknown); mode scale keeps the grey level as a
// continuous p(free) = 1 - p_occ, as MRPT does (map_server saturates the extremes); mode raw
// reads grey 0..100 as occupancy percent, anything else unknown.
//
// Frames: the map's world frame, metres. The origin is the world position of the lower-left
// corner of the lower-left cell (ROS convention); image row 0 is the top (max y) row. Origins
// are kept exactly (as floats) even when they are not multiples of the resolution, which
// COccupancyGridMap2D::setSize() would round. Occupancy follows MRPT: p(free), 0 = occupied,
// 1 = free, 0.5 = unknown.
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

/// Loads a grid map, choosing the format from the extension. For images, `geometry`
/// overrides the resolution and origin of any sidecar; without either, 0.05 m/cell and origin
/// (0,0) are used. Throws InputError naming the file for a missing, unreadable or corrupt
/// file, an unknown extension, bad metadata, or a map with no free cell (p(free) > 0.5)
/// ("map has no free cells").
mrpt::maps::COccupancyGridMap2D loadGridMap(
    const std::string& path, const std::optional<GridMapGeometry>& geometry = std::nullopt);

/// Saves `map`, choosing the format from the extension (.gridmap, .gridmap.gz, .png, .yaml,
/// .yml, .pgm). Image formats also write their metadata (.png: "<stem>.yaml" sidecar; .yaml:
/// "<stem>.pgm" image), so that loadGridMap restores the geometry. Atomic: each file is
/// written to a temporary name and renamed. Throws std::runtime_error naming the file for an
/// unsupported extension or a write failure.
void saveGridMap(const mrpt::maps::COccupancyGridMap2D& map, const std::string& path);

/// Sets the grid's limits to exactly [originX, originX + sizeX*res] x [originY, ...] without
/// the rounding to multiples of the resolution that setSize() applies; keeps the cells.
void setGridOrigin(mrpt::maps::COccupancyGridMap2D& map, float originX, float originY);

/// Number of cells with p(free) > 0.5.
std::size_t countFreeCells(const mrpt::maps::COccupancyGridMap2D& map);

}  // namespace toposlam::io
