#pragma once
// The rigid 2D transform (rotation + translation, no scale) that best maps one point set onto
// another in the least-squares sense, in closed form (Horn 1987 / Umeyama 1991 specialised to
// 2D): with both sets centred on their centroids, the optimal angle is
//     θ = atan2(Σ a_i × b_i, Σ a_i · b_i)
// and the translation maps the rotated source centroid onto the target centroid.
#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>

#include <vector>

namespace toposlam::evaluation {

/// T minimising Σ |T ⊕ source[i] − target[i]|² (T as a pose: x, y in m, phi in rad). The two
/// sets must have the same size (std::invalid_argument otherwise). Empty sets give the
/// identity, one point a pure translation; for a degenerate set (all points equal) the angle
/// is 0.
mrpt::math::TPose2D alignRigid2D(const std::vector<mrpt::math::TPoint2D>& source,
                                 const std::vector<mrpt::math::TPoint2D>& target);

}  // namespace toposlam::evaluation
