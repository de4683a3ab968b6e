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

}  // namespace toposlam::cli
