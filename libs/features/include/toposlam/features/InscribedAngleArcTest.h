#pragma once
// Arc rejection for the graph-matching paper's convex-convex segments (its ref. [16]: Xavier
// et al., "Fast line, arc/circle and leg detection from laser scan data in a Player driver",
// ICRA 2005). Every point P of a circular arc sees the arc's two extremes A, B under the same
// inscribed angle APB; on a straight line that angle is ~180 deg. Points whose inscribed angles
// have a mean in [90, 135] deg and a standard deviation below 8.6 deg form an arc.
// Points within 10 % (by count) of either extreme are left out: their angle is dominated by
// range noise on the very short chord to the extreme.
#include <toposlam/features/ScanPoints.h>

namespace toposlam::features {

struct InscribedAngleArcTest {
    double minMeanAngle = M_PI / 2;         ///< rad (90 deg)
    double maxMeanAngle = 0.75 * M_PI;      ///< rad (135 deg)
    double maxAngleStd = 8.6 * M_PI / 180;  ///< rad

    /// True when canonical readings begin..end (all valid) look like a circular arc.
    bool isArc(const ScanPoints& pts, std::size_t begin, std::size_t end) const;
};

}  // namespace toposlam::features
