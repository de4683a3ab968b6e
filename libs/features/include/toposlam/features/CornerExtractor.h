#pragma once
// Corner extraction without iteration (Liu, Ren, He 2021, "Method for extracting corner
// feature from 2D laser SLAM"), steps 1-5, one file per step:
//   1. slope difference dk of every reading (SlopeDifference, eq. 2) and the split into lines
//      at breakpoints and corners (SlopeDifferenceSplit);
//   2. merge of over-segmented neighbours by the angle threshold (SegmentMerge, eq. 3);
//   3. corner position fix (CornerFix);
//   4. two-point line fit (TwoPointLineFit), or least squares for comparison
//      (LeastSquaresLineFit);
//   5. corners as intersections of the fitted lines (CornerIntersection, FeatureAssembly).
// Paper parameters: theta_th = 0.3, dk_th = 1.0, alpha = 0.6.
//
// Two variants, measured side by side in benchmark B1:
//  - paperExact = true: eq. (2) and the breakpoint / corner rules exactly as printed.
//  - default (robust; each step documents its deviation): dk in exact form, smoothed, over a
//    range-adaptive baseline with noise-aware thresholds (SlopeDifference.h); breaks at
//    invalid readings and at range jumps (JumpDetector.h) instead of the opposite-sign rule;
//    one corner per dk bump (SlopeDifferenceSplit.h); segments shorter than the baseline their
//    corners were measured over are dropped, lines whose residual exceeds the noise too,
//    neighbours that are one line within the noise are merged, and two lines that are pieces
//    of one small circle make no corner (FeatureAssembly.h, ArcCornerTest.h). The range noise
//    sigma comes from the scan (CObservation2DRangeScan::stdError) or from rangeNoiseStd.
// Both: invalid / zero / max-range / NaN readings are breaks, angles replace slopes, very
// short segments are dropped, any field of view and either beam order give the same corners.
//
// Output (ScanFeatures, sensor frame): segments, corners (with covariance), endpoints = every
// corner (convex / concave) and every jump. Not thread-safe (one workspace per object).
#include <toposlam/config/Options.h>
#include <toposlam/features/FeatureAssembly.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/features/JumpDetector.h>
#include <toposlam/features/LinePart.h>
#include <toposlam/features/ScanPoints.h>
#include <toposlam/features/SlopeDifference.h>

#include <vector>

namespace toposlam::features {

/// Section [CornerExtractor] of config_ini/features.ini.
struct CornerExtractorOptions : public config::Options {
    double dkThreshold = 1.0;     ///< dk_th: breakpoint threshold on |dk| (paper)
    double alpha = 0.6;           ///< corners need |dk| > alpha * dk_th (paper)
    double thetaThreshold = 0.3;  ///< theta_th: merge when tan(angle) < it (paper)
    bool paperExact = false;      ///< the paper's rules as printed, no noise model
    /// Range noise (m) when the scan does not state one (or useScanStdError is false).
    double rangeNoiseStd = 0.01;
    /// Take the range noise from the scan's stdError field (MRPT's default there is 0.01).
    bool useScanStdError = true;
    double noiseSigmas = 3;    ///< z: a corner must stand z noise sigmas above noise
    unsigned minBaseline = 3;  ///< readings each side for dk (robust variant; paper: 1)
    double minValidRange = 0;  ///< m; nearer readings are invalid
    JumpDetectorOptions jumps;
    FeatureAssemblyOptions assembly;

    /// Parts that are no line are cut, corners need an angle known to 3 sigmas within
    /// theta_th's turn (FeatureAssembly.h).
    CornerExtractorOptions() {
        assembly.splitNonLines = true;
        assembly.cornerAngleSigmas = 3;
    }
    void declare(config::OptionsSchema& s) override;
};

class CornerExtractor : public FeatureExtractor {
  public:
    CornerExtractorOptions options;

    CornerExtractor() = default;
    explicit CornerExtractor(const CornerExtractorOptions& o) : options(o) {}

    void extract(const mrpt::obs::CObservation2DRangeScan& scan, ScanFeatures& out) override;
    std::string name() const override;
    void loadOptions(const mrpt::config::CConfigFileBase& cfg,
                     const std::string& section) override {
        options.loadFromConfigFile(cfg, section);
    }
    void dumpOptions(std::ostream& out) const override { options.dumpToTextStream(out); }

    /// The range noise (m) this extractor assumes for `scan` (0 in paperExact mode).
    double rangeNoise(const mrpt::obs::CObservation2DRangeScan& scan) const;

    /// Intermediate results of the last extract() (canonical order), for inspection/tests.
    const ScanPoints& points() const { return points_; }
    const SlopeDifference& slopeDifference() const { return slopeDifference_; }

  private:
    ScanPoints points_;
    JumpDetector jumpDetector_;
    std::vector<PointRun> runs_;
    SlopeDifference slopeDifference_;
    std::vector<LinePart> parts_;
    std::vector<std::uint32_t> peaks_;
    FeatureAssembly assembly_;
};

}  // namespace toposlam::features
