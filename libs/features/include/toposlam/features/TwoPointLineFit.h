#pragma once
// Corner paper, step 4: the two-point line fit. The readings of a segment are split at the
// middle one; the mean of each half is a new point, and the line through the two means
// replaces least squares. Both halves get the same number of points (the middle one of an odd
// count is left out), so the line also passes through the centroid of the points it uses, as
// the least-squares line does; its direction is a little noisier (3/4 of least squares'
// statistical efficiency for evenly spread points), which the covariance accounts for.
#include <toposlam/features/LineFit.h>

namespace toposlam::features {

/// Canonical readings begin..end (inclusive, all valid). ok = false for fewer than 2 points.
LineFit fitTwoPoint(const ScanPoints& pts, std::size_t begin, std::size_t end);

}  // namespace toposlam::features
