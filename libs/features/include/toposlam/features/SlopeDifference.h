#pragma once
// Corner paper, eq. (2): the slope difference of a reading,
//     dk(i) = (r_i - r_{i-1}) / (r_{i-1} dtheta) - (r_{i+1} - r_i) / (r_i dtheta),
// i.e. k(before) - k(after), where k = tan(phi) is the slope of the chord to the neighbour
// relative to the perpendicular of the beam (eq. 1, small-angle form). On a straight line the
// slopes of successive chords agree, so dk ~ 0; a corner gives a peak, a break two peaks of
// opposite sign.
//
// Noise-robust generalisation (a documented deviation; the paper's form stays available):
//  - the chords span s beams on each side instead of one, with tan(phi) computed exactly,
//        dk_s(i) = (r_i (1/r_{i-s} + 1/r_{i+s}) - 2 cos(s dtheta)) / sin(s dtheta),
//    which is exactly 0 on any straight line (eq. 1's approximation is not: it drifts by
//    ~ s dtheta (1 + k^2) along a wall, a lot at grazing incidence once s > 1);
//  - s is at least minBaseline (3): with s = 1 a corner that falls between two readings
//    splits its dk between them (each gets about half, and a 135-degree corner then passes
//    alpha * dk_th at neither); with s >= 3 the reading next to the corner keeps >= 5/6 of it;
//  - s adapts to the range: range noise sigma moves dk_s by sqrt(6) sigma / b (b = r s dtheta,
//    the chord), so s is the smallest baseline whose b keeps that below threshold / z. Where a
//    run is too short for it, s is clipped and the reading's threshold raised to z times the
//    noise of dk_s instead, so that noise never passes as a corner.
#include <toposlam/features/JumpDetector.h>
#include <toposlam/features/ScanPoints.h>

#include <cstdint>
#include <vector>

namespace toposlam::features {

/// Eq. (2) exactly as printed (small-angle form, one beam each side). Ranges in m, step in rad.
inline double slopeDifferencePaper(double rPrev, double r, double rNext, double step) {
    return (r - rPrev) / (rPrev * step) - (rNext - r) / (r * step);
}

/// Exact slope difference over a baseline of angle a = s * step on each side.
inline double slopeDifferenceExact(double rPrev, double r, double rNext, double cosA, double sinA) {
    return (r * (1 / rPrev + 1 / rNext) - 2 * cosA) / sinA;
}

/// dk of every reading of a scan, per run, with the threshold each reading must pass.
class SlopeDifference {
  public:
    /// dk(k) for canonical reading k; 0 where undefined (run ends, invalid readings).
    std::vector<double> dk;
    /// Baseline s (beams) used at k; 0 where dk is undefined.
    std::vector<std::uint32_t> baseline;
    /// |dk| a corner at k must exceed: cornerThreshold, raised where noise demands it.
    std::vector<double> threshold;

    /// paperForm: eq. (2) as printed with s = 1 (sigma ignored). Otherwise the exact form with
    /// the range-adaptive baseline (at least minBaseline readings) for range noise sigma (m);
    /// z: noise margin in sigmas.
    void compute(const ScanPoints& pts, const std::vector<PointRun>& runs, bool paperForm,
                 double cornerThreshold, double sigma, double z, unsigned minBaseline = 3);

    bool defined(std::size_t k) const { return baseline[k] != 0; }

    /// The chord (m) over which dk_s has noise threshold / z for range noise sigma (m):
    /// z sqrt(6) sigma / threshold.
    static double noiseChord(double sigma, double z, double threshold) {
        return z * 2.449489742783178 * sigma / threshold;
    }

  private:
    std::vector<double> cosTable_, sinTable_;  // cos/sin(s * step), s = 0..
    double tableStep_ = -1;
};

}  // namespace toposlam::features
