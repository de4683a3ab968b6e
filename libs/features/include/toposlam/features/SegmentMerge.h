#pragma once
// Corner paper, step 2: merging over-segmented lines. Two neighbours of L joined by a corner
// (Lp = 1) are one line when the angle between them is small, eq. (3):
//     tan(theta) = |(k1 - k2) / (1 + k1 k2)| < theta_th    (theta_th = 0.3, i.e. 16.7 deg),
// k1, k2 the slopes of the chords from each part's first to its last reading. The merged part
// takes the first one's start and the second one's end, and is compared with the next.
//
// Slopes are never formed: with chord directions d1, d2, tan(theta) = |d1 x d2| / (d1 . d2),
// which is the same number and is defined for vertical lines. The dot product must also be
// positive: the paper's formula measures lines, so it would merge a hairpin (two chords
// pointing back at each other, a spike) as if it were straight.
#include <toposlam/features/LinePart.h>
#include <toposlam/features/ScanPoints.h>

#include <vector>

namespace toposlam::features {

/// True when the chords of a and b (a before b) are within eq. (3)'s angle threshold.
bool chordsAlmostParallel(const ScanPoints& pts, const LinePart& a, const LinePart& b,
                          double thetaThreshold);

/// Merges in place (one pass, each merged part compared again with its new neighbour).
void mergeSegments(const ScanPoints& pts, double thetaThreshold, std::vector<LinePart>& parts);

}  // namespace toposlam::features
