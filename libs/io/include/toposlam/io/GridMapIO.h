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
//                           Written exactly as ROS map_saver writes a map: "<stem>.pgm", an
//                           8-bit trinary PGM (occupied 0, free 254, unknown 205), and the YAML
//                           with "mode: trinary", negate 0, occupied_thresh 0.65, free_thresh
//                           0.196, so map_server loads every cell as the grid has it: p(occ) =
//                           1 - p(free) > 0.65 -> 100, < 0.196 -> 0, otherwise -1 (unknown).
//   .png                    8-bit grey picture of p(free) for people to look at (0 black =
//                           occupied, 255 white = free, 128 = unknown, as MRPT draws grids),
//                           plus the ROS pair "<stem>.yaml" + "<stem>.pgm" beside it (as .yaml).
//   .pgm                    as .yaml (trinary PGM + "<stem>.yaml").
//   .png .pgm .bmp .jpg .jpeg .tif .tiff on input: the sidecar "<stem>.yaml" is used when it
//                           exists and its `image` is this file (or, for a .png, the
//                           "<stem>.pgm" of the pair written with it: the picture then takes the
//                           YAML's geometry and p(free) = grey / 255); otherwise the image is
//                           bare: p(free) = grey / 255 (colour and alpha images are read as
//                           grey), with the geometry given by the caller (default 0.05 m/cell,
//                           origin (0,0)); a bare picture of map_saver's three greys alone
//                           (0, 205, 254) is read as map_server reads it with map_saver's
//                           YAML (205: unknown). Whether a bare picture is a grid at all or a
//                           drawn floor plan is the caller's to decide (MapImageKind.h).
// Size limits: at most kMaxGridMapCells cells, checked before they are allocated (from a
// .gridmap's stored limits, an image's header).
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
#include <vector>

namespace toposlam::io {

/// Most cells a grid map read from a file may have: 2^28 (16 384 x 16 384; a building at
/// 5 cm is a few million). Checked before the cells are allocated.
constexpr unsigned long long kMaxGridMapCells = 1ULL << 28;

/// Cell sizes (m) a map may have: grids keep the resolution as a float, and a cell under a
/// millimetre is no map anyone drew (a 1e-300 m cell became 0 and failed an MRPT assertion).
constexpr double kMinCellSize = 0.001, kMaxCellSize = 100;
/// Largest |x| or |y| (m) of a map's origin.
constexpr double kMaxMapOrigin = 1e6;

/// p(free) above which a pixel of a drawn or scanned floor plan read as p(free) = grey / 255 is
/// free: grey >= 250 (249 / 255 = 0.976, 250 / 255 = 0.980), the reading of Bormann et al.'s
/// room segmentation benchmark. Every app that reads a map as a drawn plan uses it (--drawn,
/// cli::MapReadingArgs).
constexpr double kDrawnPlanFreeAbove = 0.98;

/// The greys of ROS map_saver's trinary picture, which saveGridMap writes too.
constexpr unsigned char kMapSaverOccupiedGrey = 0;
constexpr unsigned char kMapSaverUnknownGrey = 205;
constexpr unsigned char kMapSaverFreeGrey = 254;

/// What a caller states of an image map's geometry. Each value given replaces the sidecar's
/// (or .yaml's) and only that one: the rest, and how the greys are read, stay the sidecar's.
struct GridMapGeometry {
    std::optional<double> resolution;  ///< m per cell
    std::optional<double> originX;     ///< world x (m) of the lower-left corner of the image
    std::optional<double> originY;     ///< world y (m) of the lower-left corner of the image
};

/// Loads a grid map, choosing the format from the extension. For images, what `geometry`
/// gives overrides that value of the sidecar; what neither gives is 0.05 m/cell and origin
/// (0,0). Throws InputError naming the file for a missing, unreadable or corrupt
/// file, an unknown extension, bad metadata, or a map with no free cell (p(free) > 0.5)
/// ("map has no free cells").
mrpt::maps::COccupancyGridMap2D loadGridMap(
    const std::string& path, const std::optional<GridMapGeometry>& geometry = std::nullopt);

/// Whether `path` names a grid map by its extension (.gridmap, .gridmap.gz, .yaml, .yml, .png,
/// .pgm, .bmp, .jpg, .jpeg, .tif, .tiff; any case), rather than a laser log.
bool isGridMapPath(const std::string& path);

/// True when loadGridMap reads `path` as a bare picture: an image format without the .yaml
/// sidecar that states its geometry and how its greys are meant (see above). Such a picture
/// may be a grid (grey = p(free)) or a drawn floor plan: see MapImageKind.h.
bool isBareMapImage(const std::string& path);

/// Every file loadGridMap(path) reads: `path`, and the "<stem>.yaml" beside a picture (read to
/// tell whether it is the picture's sidecar) or the picture a .yaml names, so that an app can
/// refuse to write over any of them before it starts. Does not throw (a .yaml it cannot read
/// names no picture).
std::vector<std::string> gridMapFilesRead(const std::string& path);

/// Every file saveGridMap(map, path) writes: `path` and the ROS pair of a .png, .yaml or .pgm.
std::vector<std::string> gridMapFilesWritten(const std::string& path);

/// Saves `map`, choosing the format from the extension (.gridmap, .gridmap.gz, .png, .yaml,
/// .yml, .pgm). Image formats also write the ROS pair (.png: "<stem>.yaml" + "<stem>.pgm";
/// .yaml: "<stem>.pgm"; .pgm: "<stem>.yaml"), so that ROS map_server and loadGridMap restore
/// the geometry and the cells. Atomic: each file is written to a temporary name and renamed.
/// Throws std::runtime_error naming the file for an unsupported extension or a write
/// failure.
void saveGridMap(const mrpt::maps::COccupancyGridMap2D& map, const std::string& path);

/// Sets the grid's limits to exactly [originX, originX + sizeX*res] x [originY, ...] without
/// the rounding to multiples of the resolution that setSize() applies; keeps the cells.
void setGridOrigin(mrpt::maps::COccupancyGridMap2D& map, float originX, float originY);

/// Number of cells with p(free) > 0.5.
std::size_t countFreeCells(const mrpt::maps::COccupancyGridMap2D& map);

}  // namespace toposlam::io
