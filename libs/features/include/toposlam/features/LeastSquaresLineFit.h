#pragma once
// Orthogonal (total) least-squares line fit: the line through the centroid along the
// principal axis of the points' scatter; minimises the sum of squared point-to-line distances.
// The classic reference the corner paper's two-point fit is compared with.
#include <toposlam/features/LineFit.h>

namespace toposlam::features {

/// Canonical readings begin..end (inclusive, all valid). ok = false for fewer than 2 points.
LineFit fitLeastSquares(const ScanPoints& pts, std::size_t begin, std::size_t end);
/// The same from accumulated sums (any set of points).
LineFit fitLeastSquares(const PointSums& sums);

}  // namespace toposlam::features
