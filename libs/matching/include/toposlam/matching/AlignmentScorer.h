#pragma once
// How well a candidate pose explains the current scan, judged by the reference scan's own
// readings (free-space consistency). Every valid point of the current scan is moved into the
// reference sensor's frame and looked up by bearing in the reference scan (O(1), no search
// tree); against the reference readings of the nearest beams it is
//   - an inlier     when it lies within inlierDistance of the reference surface (the points
//                   and the polyline through neighbouring reference points), and the current
//                   sensor is on the side of that polyline the reference sensor saw it from:
//                   the other face of a 10 cm wall is not the same surface;
//   - a violation   when it lies in front of the reference readings (that beam and both
//                   neighbours) by more than that: the reference sensor saw through the place
//                   where the current scan saw a surface, so the pose (or a moving obstacle)
//                   is wrong there;
//   - unverifiable  when it is outside the reference's field of view, behind a reference
//                   reading (occluded from the reference), or the reference beam has no return.
//                   Those outside the field of view are also counted apart (outOfView): the
//                   reference could not have seen them at any range, so they say nothing about
//                   how much of what both sensors could see the pose explains.
// inlierFraction = inliers / (inliers + violations) is a quality in [0, 1] that does not
// punish partial overlap; the inlier count says how much of the scan supports the pose.
#include <mrpt/poses/CPose2D.h>
#include <toposlam/config/OptionsSchema.h>
#include <toposlam/matching/PolarScan.h>

#include <cstddef>

namespace toposlam::matching {

struct AlignmentScoreOptions {
    double inlierDistance = 0.10;  ///< m
    long searchBeams = 2;          ///< reference beams looked at on each side of the bearing
    std::size_t stride = 1;        ///< score every stride-th current beam
    /// Two neighbouring reference points farther apart than this (m) plus 3 beam arcs are
    /// not joined into a polyline piece (a range jump, not a surface).
    double maxJoinDistance = 0.30;

    /// Its .ini keys (GraphScanMatcher.h gives them a prefix).
    void declare(config::OptionsSchema& s);
};

struct AlignmentScore {
    std::size_t inliers = 0, violations = 0, unverifiable = 0;
    std::size_t outOfView = 0;      ///< of the unverifiable: outside the reference's field of view
    double inlierSquaredError = 0;  ///< sum over inliers of the squared distance (m^2)

    std::size_t verified() const { return inliers + violations; }
    double inlierFraction() const {
        return verified() > 0 ? double(inliers) / double(verified()) : 0.0;
    }
    double inlierRms() const;  ///< m
};

/// Scores `pose` (current sensor frame in the reference sensor frame).
AlignmentScore scoreAlignment(const PolarScan& reference, const PolarScan& current,
                              const mrpt::poses::CPose2D& pose,
                              const AlignmentScoreOptions& options = {});

}  // namespace toposlam::matching
