#pragma once
// The --drawn / --grid pair of the apps that read a grid map (toposlam-rooms, toposlam-sim,
// toposlam-plan): how a bare picture is read, as a drawn floor plan (only white is free) or as
// an occupancy grid (grey = p(free)). Without either the reading is guessed from the picture
// (io/MapImageKind.h) and a note on stderr says which and why, so that no plan is silently
// read as a grid whose light-grey walls are free space. Maps that state their reading (.gridmap,
// .yaml, a picture with its .yaml sidecar) are grids unless --drawn is given.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <toposlam/cli/NumberArg.h>
#include <toposlam/io/GridMapIO.h>

#include <optional>
#include <string>

namespace toposlam::cli {

class MapReadingArgs {
  public:
    /// Adds --drawn and --grid to `cmd`. `drawnEffect`: what --drawn does in this app (one or
    /// two sentences, appended to the common help).
    MapReadingArgs(TCLAP::CmdLine& cmd, const std::string& drawnEffect);

    /// True when the map at `mapPath` is to be read as a drawn plan: --drawn, or a bare picture
    /// guessed to be one. Prints the note for a guessed reading to stderr. Throws UsageError
    /// for --drawn with --grid, io::InputError for an unreadable picture.
    bool readAsDrawnPlan(const std::string& mapPath) const;
    /// --drawn or --grid was given (an app whose input may be something else refuses them
    /// then).
    bool given() const { return drawn_.isSet() || grid_.isSet(); }

  private:
    mutable TCLAP::SwitchArg drawn_, grid_;  // MRPT's TCLAP: getValue() is not const
};

/// The --resolution / --origin pair of the apps that read a map picture (toposlam-convert,
/// toposlam-rooms, toposlam-sim). Each replaces that one value of the picture's .yaml sidecar
/// (or of a .yaml map): the rest of the sidecar, and how it reads the greys, is kept, so that
/// --resolution alone does not move the map to (0,0) nor --origin alone rescale it.
class MapGeometryArgs {
  public:
    explicit MapGeometryArgs(TCLAP::CmdLine& cmd);

    /// What was given, for io::loadGridMap; nullopt when neither. Throws UsageError for a
    /// malformed --origin.
    std::optional<io::GridMapGeometry> geometry() const;
    /// --resolution or --origin was given (an app whose input is no map refuses them then).
    bool given() const { return resolution_.isSet() || origin_.isSet(); }

  private:
    NumberArg<double> resolution_;
    mutable TCLAP::ValueArg<std::string> origin_;  // MRPT's TCLAP: getValue() is not const
};

}  // namespace toposlam::cli
