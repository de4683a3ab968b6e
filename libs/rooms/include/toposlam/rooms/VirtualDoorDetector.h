#pragma once
// Step 4 of the virtual-door method (sec. 1.5, eq. 10): from every search-path cell, look along
// the first main direction, on both sides, for the nearest non-free cell. The two cells found
// are the jambs of a virtual door when their distance matches the door width:
//     | |n1 - n2| - w / r | < delta_w / r                                           (eq. 10)
// (w door width, delta_w its tolerance, r the cell size). When phi1 gives no door, phi2 is
// tried.
//
// Deviation (Options::localDirection, on by default): the paper assumes rectangular rooms
// aligned with two main directions (assumption 1), so a door in a wall of any other direction
// (pentagonal or curved buildings, B4's office_e and lab_intel) is never crossed at right
// angles. TopoSLAM also searches, from every cell, across the ridge of the clearance (the
// direction in which the distance to the walls falls off fastest, Clearance::acrossRidge): in
// a doorway the clearance peaks between the jambs, so this is the door line whatever its
// orientation. Every direction that passes eq. 10 gives a candidate (the paper: only the first);
// the filters keep the narrowest of each group.
#include <toposlam/rooms/FreeSpaceBinarizer.h>

#include <opencv2/core/mat.hpp>

#include <vector>

namespace toposlam::rooms {

/// A candidate door: the cut between two jamb cells, in pixels of the map image.
struct VirtualDoor {
    cv::Point jambA;     ///< first non-free cell found on one side
    cv::Point jambB;     ///< ... and on the other side
    double width = 0;    ///< |jambA - jambB|, pixels (between cell centres)
    int direction = 0;   ///< index of the search direction that found it (0: phi1, 1: phi2)
    cv::Point pathCell;  ///< the search-path cell it was found from
};

class VirtualDoorDetector {
  public:
    struct Options {
        /// w (m) and delta_w (m): openings of w +- delta_w count as doors. The default range,
        /// 0.6-1.6 m, spans the single-leaf doors of building standards (DIN 18101: 0.625-
        /// 1.135 m clear width) and narrow double doors; the paper uses a single known door
        /// leaf width.
        double doorWidth = 1.1;
        double doorWidthTolerance = 0.5;
        /// Also search across the clearance ridge at each cell, and keep every passing
        /// direction (deviation, see above). Off: the paper's phi1-then-phi2.
        bool localDirection = true;
    };

    VirtualDoorDetector() = default;
    explicit VirtualDoorDetector(const Options& options) : options_(options) {}

    /// `directions`: search directions in image radians (the paper: phi1, phi2), tried in
    /// order, the first that yields a door wins (at most one door per path cell). With
    /// localDirection, every direction that yields a door gives one, `localDirections[i]`
    /// included for pathCells[i]. Each cut (pair of jamb cells) is returned once, as the first
    /// path cell found it.
    std::vector<VirtualDoor> detect(const FreeSpace& space, const std::vector<cv::Point>& pathCells,
                                    const std::vector<double>& directions,
                                    const std::vector<double>& localDirections = {}) const;

    /// The first cell that is not free in `free` (CV_8U, 0 = not free; outside = not free)
    /// along the ray from the centre of `from` in direction (ux, uy), no farther than
    /// `maxDistance` pixels. Every cell the ray touches is visited; where it passes exactly
    /// through a cell corner, both side cells are checked, so a diagonal wall stops it.
    static bool castRay(const cv::Mat& free, const cv::Point& from, double ux, double uy,
                        double maxDistance, cv::Point& hit);

    const Options& options() const { return options_; }

  private:
    Options options_;
};

}  // namespace toposlam::rooms
