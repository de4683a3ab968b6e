#pragma once
// Is this "corner" really a bend in a round object? (A deviation from the corner paper, which
// assumes polygonal surroundings: a pillar, a bin or a person's leg make a chain of short lines
// with a "corner" at every joint.) The readings of the two segments that meet at the corner
// are fitted with one circle (algebraic fit, Kasa 1976, from running sums); when that circle
// is small (radius < maxRadius) and its geometric residual is no worse than the two lines'
// by more than the two lines' extra parameters explain (4 sigma^2, Akaike), the joint is a
// sample of an arc, not a corner. At a true corner one circle fits two straight walls far
// worse than the two lines; on an arc the two chords leave a sagitta that the circle does not.
#include <toposlam/features/ScanPoints.h>

#include <cstddef>

namespace toposlam::features {

struct ArcCornerTest {
    double maxRadius = 1.0;  ///< m; larger arcs (curved walls) are left alone

    /// Readings a0..a1 and b0..b1 (canonical, valid) are the two segments; lineRss the sum of
    /// their squared distances to their own lines (m^2); sigma the range noise (m).
    bool isArc(const ScanPoints& pts, std::size_t a0, std::size_t a1, std::size_t b0,
               std::size_t b1, double lineRss, double sigma) const;
};

}  // namespace toposlam::features
