#pragma once
// A grid map converted from one file format to another (GridMapIO.h lists them): what
// toposlam-convert does with maps.
#include <toposlam/io/GridMapIO.h>

#include <cstddef>
#include <optional>
#include <string>

namespace toposlam::io {

struct MapConversionSummary {
    unsigned sizeX = 0, sizeY = 0;    ///< cells
    double resolution = 0;            ///< m per cell
    double originX = 0, originY = 0;  ///< m, lower-left corner of the grid
    std::size_t freeCells = 0;        ///< cells with p(free) > 0.5
};

/// Loads `inputPath` (with `geometry` for bare images, see loadGridMap) and saves it as
/// `outputPath`. `drawnPlan`: the input is a drawn floor plan (MapImageKind.h), whose cells are
/// free only where white (p(free) > kDrawnPlanFreeAbove) and are written occupied (p(free) 0)
/// everywhere else, walls, furniture and background alike, so that a grid reader sees the plan
/// as it is meant. Throws InputError for bad input, std::runtime_error when the output cannot
/// be written; no output file is left then.
MapConversionSummary convertGridMap(const std::string& inputPath, const std::string& outputPath,
                                    const std::optional<GridMapGeometry>& geometry,
                                    bool drawnPlan = false);

/// One line: "<input>: W x H cells of R m, origin (x, y) m, N free cells -> <output>".
std::string describe(const MapConversionSummary& summary, const std::string& inputPath,
                     const std::string& outputPath);

}  // namespace toposlam::io
