#pragma once
// Step 3 of the virtual-door method (sec. 1.4.3, eqs. 8-9): the two main directions of the
// rooms. Segment directions are binned in bins of width 2*delta_phi over [0, pi); each segment
// votes with its length. phi1 is the direction of the bin with most votes (eq. 8); phi2 is the
// voted direction closest to perpendicular to phi1 (eq. 9). A bin's direction is the
// length-weighted mean direction of its segments.
#include <toposlam/rooms/LineSegment.h>

#include <vector>

namespace toposlam::rooms {

struct MainDirections {
    /// rad in [0, pi), measured in the image (x right, y down); the world direction is -phi
    /// because image rows grow towards -y.
    double phi1 = 0.0;
    double phi2 = M_PI / 2;
    /// Votes (summed segment length, pixels) per bin; bin k is centred on k * binWidth.
    std::vector<double> votes;
    double binWidth = 0.0;  ///< rad
};

class MainDirectionVoter {
  public:
    struct Options {
        double maxAngleDeg = 5.0;  ///< delta_phi (deg); bins are 2 * delta_phi wide
    };

    MainDirectionVoter() = default;
    explicit MainDirectionVoter(const Options& options) : options_(options) {}

    /// Without any segment, the image axes (0 and pi/2).
    MainDirections vote(const std::vector<LineSegment>& lines) const;

  private:
    Options options_;
};

}  // namespace toposlam::rooms
