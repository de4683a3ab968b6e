#include <toposlam/cli/CommandLine.h>
#include <toposlam/cli/MapReadingArgs.h>
#include <toposlam/cli/UsageError.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/MapImageKind.h>

#include <iostream>

namespace toposlam::cli {

MapReadingArgs::MapReadingArgs(TCLAP::CmdLine& cmd, const std::string& drawnEffect)
    : drawn_("", "drawn",
             "Read the map as a drawn or scanned floor plan: only white pixels (grey 250 and "
             "above, p(free) > 0.98) are free, every other pixel is an obstacle, whatever its "
             "grey. " +
                 drawnEffect +
                 " Default for a bare picture (no .yaml beside it) whose non-white pixels are "
                 "not mostly mid grey (unknown space): see --grid.",
             cmd, false),
      grid_("", "grid",
            "Read a bare picture as an occupancy grid, grey = p(free): light greys free, mid "
            "grey unknown, dark occupied. Default for a picture whose non-white pixels are "
            "mostly mid grey and that has dark ones (a SLAM map saved as a picture), and for "
            ".gridmap, .yaml and pictures with their .yaml sidecar. Without --drawn or --grid "
            "a bare picture's reading is guessed, with a note on stderr.",
            cmd, false) {}

bool MapReadingArgs::readAsDrawnPlan(const std::string& mapPath) const {
    if (drawn_.getValue() && grid_.getValue())
        throw UsageError("--drawn and --grid: give one or the other");
    if (drawn_.getValue() || grid_.getValue() || !io::isBareMapImage(mapPath))
        return drawn_.getValue();
    const io::MapImageKindGuess guess = io::guessMapImageKind(mapPath);
    const bool drawn = guess.kind == io::MapImageKind::DrawnPlan;
    std::cerr << "note: " << mapPath << ": read as "
              << (drawn ? "a drawn floor plan (only white is free)"
                        : "an occupancy grid (grey = p(free))")
              << ": " << guess.reason() << "; " << (drawn ? "--grid" : "--drawn")
              << " reads it the other way\n";
    return drawn;
}

MapGeometryArgs::MapGeometryArgs(TCLAP::CmdLine& cmd)
    : resolution_("", "resolution",
                  "Cell size in m of a map picture. Replaces its .yaml sidecar's resolution and "
                  "only that: the sidecar's origin and reading of the greys are kept. Default: "
                  "the sidecar's, else 0.05",
                  0.05, NumberRange<double>::closed(io::kMinCellSize, io::kMaxCellSize), "m", cmd),
      origin_("", "origin",
              "World x,y (m) of the lower-left corner of a map picture. Replaces its .yaml "
              "sidecar's origin and only that: the sidecar's resolution and reading of the "
              "greys are kept. Default: the sidecar's, else 0,0",
              false, "", "x,y", cmd) {}

std::optional<io::GridMapGeometry> MapGeometryArgs::geometry() const {
    if (!given())
        return std::nullopt;
    io::GridMapGeometry g;
    if (resolution_.isSet())
        g.resolution = resolution_.getValue();
    if (origin_.isSet()) {
        const auto xy = parseNumberList(origin_.getValue(), 2, "--origin");
        g.originX = xy[0];
        g.originY = xy[1];
    }
    return g;
}

}  // namespace toposlam::cli
