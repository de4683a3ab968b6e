#pragma once
// Jump points (graph-matching paper, sec. 2.1, eq. 1): two consecutive readings are on
// different surfaces when the distance between their points exceeds the dynamic threshold
//     k * psi * d       (k = 15, psi = angular step, d = range),
// i.e. when the surface would have to be seen at more than acos(1/k) = 86 deg incidence.
// The nearer point of a jump pair is an occluding edge: a convex endpoint ("Jump").
//
// Deviations from the paper, both keeping its intent:
//  - d is the smaller of the two ranges, so the test does not depend on the scan direction;
//  - the gap must also exceed noiseSigmas * sqrt(2) * sigma (sigma = range noise, m), so that
//    range noise alone never makes a jump at short range, where k * psi * d is tiny.
// The result is the scan cut into runs: maximal stretches of consecutive valid readings with
// no jump inside, the unit every extractor works on.
#include <toposlam/config/Options.h>
#include <toposlam/features/ScanFeatures.h>
#include <toposlam/features/ScanPoints.h>

#include <cstdint>
#include <vector>

namespace toposlam::features {

/// Consecutive valid readings begin..end (canonical indices, inclusive) on one surface.
struct PointRun {
    std::uint32_t begin = 0, end = 0;
    /// Jump when that end is the nearer point of a jump; Open for the far side of a jump, an
    /// invalid neighbour or the scan border.
    EndpointType beginType = EndpointType::Open, endType = EndpointType::Open;
    std::uint32_t size() const { return end - begin + 1; }
};

/// Keys enabled, k, noise_sigmas (jump_enabled, ... inside the extractors' sections).
struct JumpDetectorOptions : public config::Options {
    bool enabled = true;     ///< false: runs are cut only at invalid readings
    double k = 15;           ///< paper's scale factor of the dynamic threshold
    double noiseSigmas = 5;  ///< noise floor of the threshold, in sigmas of a range difference
    void declare(config::OptionsSchema& s) override;
};

class JumpDetector {
  public:
    JumpDetectorOptions options;

    /// True when readings k and k+1 (both valid) are a jump; sigma: range noise (m).
    bool isJump(const ScanPoints& pts, std::size_t k, double sigma) const;
    /// Cuts the valid readings into runs (cleared first; in canonical order).
    void findRuns(const ScanPoints& pts, double sigma, std::vector<PointRun>& runs) const;
};

}  // namespace toposlam::features
