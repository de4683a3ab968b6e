#pragma once
// Corner paper, step 5: a corner is the intersection of the fitted lines of two segments that
// meet (Lp = 1). Besides the position this computes what the paper does not:
//  - the corner angle, between the two walls as they leave the corner, in (0, pi);
//  - convex / concave, seen from the sensor (a room corner is concave);
//  - the position covariance, propagated from both line fits: each line's normal offset at
//    the corner has variance sigma_j^2 (offsetVarFactor + t^2 directionVarFactor), t the
//    distance from the fit's anchor along the line, and the corner moves with both offsets.
//    sigma_j^2 is the line's residual variance (N - 2 degrees of freedom) pooled with the
//    sensor's range noise counted as 2 degrees of freedom.
#include <mrpt/math/TPoint2D.h>
#include <toposlam/features/LineFit.h>
#include <toposlam/features/ScanFeatures.h>

namespace toposlam::features {

/// Point noise variance (m^2) of a fit: its residual variance pooled with the sensor's noise.
double pointVariance(const LineFit& fit, double sensorSigma);

/// Standard deviation (rad) of the angle between two fitted lines.
double angleStd(const LineFit& a, const LineFit& b, double sensorSigma);

/// Intersection of two lines; false when they are parallel (|sin angle| < 1e-9).
bool intersectLines(const LineFit& a, const LineFit& b, mrpt::math::TPoint2D& out);

/// Corner where the line of `before` (scan order: lower bearings) meets that of `after`.
/// farBefore / farAfter: the far ends of the two segments (where the walls lead away from the
/// corner). sensorSigma: range noise (m), the floor of each line's point noise. Fills
/// position, angle, type and covariance of `out`; false when the lines are parallel.
bool intersectCorner(const LineFit& before, const LineFit& after,
                     const mrpt::math::TPoint2D& farBefore, const mrpt::math::TPoint2D& farAfter,
                     double sensorSigma, Corner& out);

}  // namespace toposlam::features
