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
//  - each of the three readings is replaced by the mean inverse range of the 2m+1 readings
//    around it (m = s/2): along a straight line 1/r is a sinusoid of the bearing, so symmetric
//    means scale all three by one factor and dk_s stays exactly 0, while the noise drops by
//    sqrt(2m+1) (without noise, m = 0);
//  - s adapts to the range: range noise sigma moves dk_s by
//    sqrt(6) sigma / (r dtheta s sqrt(2m+1)), so s is the smallest baseline that keeps this
//    below threshold / z. Where a run is too short for it, s is clipped and the reading's
//    threshold raised to z times the noise of dk_s instead, so that noise never passes as a
//    corner.
#include <toposlam/features/JumpDetector.h>
#include <toposlam/features/ScanPoints.h>

#include <cmath>
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

/// dk of every reading of a scan, per run, with the threshold each reading must pass. The
/// robust form is computed in blocks of 16 readings that share the baseline their nearest
/// reading needs: a fixed stencil on running sums of inverse ranges, a handful of operations
/// per reading.
class SlopeDifference {
  public:
    /// dk(k) = numerator[k] / scale[k] for canonical reading k (scale > 0); kept as a fraction
    /// because only a few readings need the quotient: the rest are compared (|dk| > t is
    /// |numerator| > t scale), which saves a division per reading.
    std::vector<double> numerator, scale;
    /// Baseline s (beams) used at k; 0 where dk is undefined (run ends, invalid readings).
    std::vector<std::uint32_t> baseline;
    /// |dk| a corner at k must exceed: cornerThreshold, raised where noise demands it. In the
    /// robust form it is set only where |dk| > cornerThreshold (elsewhere it is irrelevant).
    std::vector<double> threshold;
    /// The readings whose |dk| exceeds their threshold, ascending (robust form only).
    std::vector<std::uint32_t> above;

    /// paperForm: eq. (2) as printed with s = 1 (sigma ignored). Otherwise the exact form with
    /// the range-adaptive baseline (at least minBaseline readings) for range noise sigma (m);
    /// z: noise margin in sigmas.
    void compute(const ScanPoints& pts, const std::vector<PointRun>& runs, bool paperForm,
                 double cornerThreshold, double sigma, double z, unsigned minBaseline = 3);

    bool defined(std::size_t k) const { return baseline[k] != 0; }
    /// dk at reading k (defined readings only).
    double value(std::size_t k) const { return numerator[k] / scale[k]; }
    /// |dk(k)| > t.
    bool exceeds(std::size_t k, double t) const { return std::abs(numerator[k]) > t * scale[k]; }
    /// |dk(a)| > |dk(b)|.
    bool stronger(std::size_t a, std::size_t b) const {
        return std::abs(numerator[a]) * scale[b] > std::abs(numerator[b]) * scale[a];
    }

  private:
    /// The paper's eq. (2) on neighbouring readings (paperForm).
    void computePaperForm(const ScanPoints& pts, const std::vector<PointRun>& runs, double step);
    /// cos, 1/sin and noise gain per baseline, rebuilt only when the scan geometry changes.
    void updateTables(double step);
    /// inverse_ = 1/range (0 where invalid) and prefix_ = its running sums.
    void computeRunningSums(const ScanPoints& pts);
    /// Evaluates the exact form at reading i of a run [runBegin, runEnd] with baseline s (the
    /// noise-wanted one; clipped to the run here). False when it does not fit.
    bool evaluateAt(std::size_t i, std::size_t runBegin, std::size_t runEnd, std::size_t s,
                    double noiseHere);

    std::vector<double> cosTable_, invSinTable_;  // cos(s step), 1 / sin(s step), s = 0..
    std::vector<double> invGain_;                 // 1 / (s sqrt(2m + 1))
    std::vector<double> inverse_;                 // 1 / range (0 where invalid)
    std::vector<double> prefix_;                  // running sums of inverse ranges
    double tableStep_ = -1;
    bool tableSmooth_ = false;
    bool paper_ = false, smooth_ = false;
    double cornerThreshold_ = 0, noiseScale_ = 0;
    std::size_t sMin_ = 1, maxBaseline_ = 0;
};

}  // namespace toposlam::features
