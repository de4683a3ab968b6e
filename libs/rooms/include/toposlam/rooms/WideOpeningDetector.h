#pragma once
// TopoSLAM's second door pass (a deviation from the paper, Options::enabled): openings from the
// widest door's width (which eq. 10 leaves out) up to maxWidth that are still a room border. The
// open fronts of cubicles, the mouths of alcoves and 2-3 m passages between two rooms are drawn as
// room borders by people, but eq. 10 with a door-width range cannot find them, and a wider range
// for every door would cut corridors everywhere.
//
// A wide opening is searched like a door (step 4, from the search paths; across the main
// directions only, unless Options::localDirection) and must pass stricter versions of step 5's
// tests, because the wider the opening the more places look like one:
//   - both jambs end the wall the opening is in (a door needs one), neither lies in the middle
//     of a wall that runs across the door line, and the two are not on walls that go on to the
//     same side of it: the opening is framed by wall ends, never a cross-section of a corridor
//     between its side walls (DoorFilters::Options::requireBothWallEnds);
//   - the constriction is probed up to maxWidth from the door line and must open by
//     openingMargin on both sides: the opening is a waist between two wider spaces.
// The found openings join the doors before the distance filter, which prefers the narrowest of
// a group (a door in the same place wins), and the minimum-area filter, which merges through
// the widest cut first.
#include <toposlam/rooms/DoorFilters.h>
#include <toposlam/rooms/DoorSearchPaths.h>
#include <toposlam/rooms/FreeSpaceBinarizer.h>
#include <toposlam/rooms/LineSegment.h>
#include <toposlam/rooms/VirtualDoorDetector.h>

#include <opencv2/core/mat.hpp>

#include <utility>
#include <vector>

namespace toposlam::rooms {

class WideOpeningDetector {
  public:
    struct Options {
        bool enabled = true;
        /// m: openings from the widest door (doorWidth + doorWidthTolerance) up to this.
        double maxWidth = 3.0;
        /// m: how much wider than the opening the free space must become on both sides.
        double openingMargin = 0.5;
        /// Also search across the clearance ridge (as doors are, VirtualDoorDetector's
        /// localDirection). Off: along the main directions only. Where two corridors meet the
        /// ridge runs diagonally, and a cut along it spans the junction from corner to corner
        /// at 20-30 degrees to both walls, where no framing test can tell it from an opening.
        bool localDirection = false;
    };

    WideOpeningDetector() = default;
    WideOpeningDetector(const Options& options, const VirtualDoorDetector::Options& door,
                        const DoorFilters::Options& filters);

    /// The wide openings of `space` (pixels). `pathCells`: the trajectory cells, or empty to
    /// search the medial axis at the clearances of axisWidths(); `directions`: the
    /// main directions; `walls`: step 2's segments. Empty when disabled. `medialAxis`: that
    /// medial axis when the caller has it (DoorSearchPaths::fromMedialAxis over axisWidths());
    /// nullptr: found here.
    std::vector<VirtualDoor> detect(const FreeSpace& space, const Clearance& clearance,
                                    const std::vector<cv::Point>& pathCells,
                                    const std::vector<double>& directions,
                                    const std::vector<LineSegment>& walls,
                                    const WallThickness* thickness = nullptr,
                                    const std::vector<cv::Point>* medialAxis = nullptr) const;

    /// Whether detect() searches at all (enabled, and wider openings than doors allowed).
    bool searches() const { return options_.enabled && options_.maxWidth > minWidth_; }
    /// The widths {min, max} (m) of the openings it searches.
    std::pair<double, double> widths() const { return {minWidth_, options_.maxWidth}; }
    /// The widths {min, max} (m) whose middles' clearance the medial axis is searched at: from
    /// the door width w, not the widest door, because a ragged opening's middle lies nearer
    /// an obstacle than half its width (a wall end drawn cell by cell on a SLAM grid, a post
    /// beside the opening); each cut found is still measured against widths().
    std::pair<double, double> axisWidths() const { return {axisMinWidth_, options_.maxWidth}; }

    const Options& options() const { return options_; }

  private:
    Options options_;
    double minWidth_ = 0;      ///< m, the widest door
    double axisMinWidth_ = 0;  ///< m, the door width w
    VirtualDoorDetector detector_;
    DoorFilters filters_;
};

}  // namespace toposlam::rooms
