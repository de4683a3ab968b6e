#pragma once
// Corner paper, step 1: the split of a scan into the segment set L = {(Lb, Le, Lp)} by the
// slope difference dk (SlopeDifference.h).
//  - Breakpoint between i and i+1 when |dk(i)| > dk_th, |dk(i+1)| > dk_th and
//    dk(i) * dk(i+1) < 0: i ends a line, i+1 starts the next (Lp = 0).
//  - Corner at i when |dk(i)| > alpha * dk_th, |dk(i)| > |dk(i-1)| and |dk(i)| > |dk(i+1)|:
//    i ends a line and starts the next (Lp = 1).
// The runs the scan was cut into (invalid readings, and jumps when enabled) are breaks too.
//
// Robust form (the deviation that goes with the range-adaptive slope difference): breaks come
// only from the runs (JumpDetector: an explicit distance test, where the opposite-sign rule
// fires on noise), and a corner is the largest |dk| of each stretch of consecutive readings
// whose |dk| passes its noise-aware threshold with one sign: with a baseline of s beams a
// corner makes a bump 2s readings wide, not a single-reading peak. Of two such peaks closer
// than their baselines only the stronger is kept: their bumps overlap, so the chords of the
// weaker one run across the stronger corner and measure nothing of its own (this is what
// keeps a round pillar from turning into a chain of tiny "corners").
#include <toposlam/features/JumpDetector.h>
#include <toposlam/features/LinePart.h>
#include <toposlam/features/SlopeDifference.h>

#include <vector>

namespace toposlam::features {

/// Fills `parts` (cleared first). paperRules: the paper's breakpoint and corner rules on dk;
/// otherwise the robust form. dkThreshold: dk_th (breakpoints, paper rules only); the corner
/// thresholds are sd.threshold (alpha * dk_th, raised for noise). `workspace`: scratch space,
/// reused between calls.
void splitBySlopeDifference(const ScanPoints& pts, const std::vector<PointRun>& runs,
                            const SlopeDifference& sd, double dkThreshold, bool paperRules,
                            std::vector<LinePart>& parts, std::vector<std::uint32_t>& workspace);

}  // namespace toposlam::features
