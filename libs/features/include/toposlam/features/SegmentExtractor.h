#pragma once
// Convex / concave endpoints and the segments between them (Zhang, Yang 2018, "Single-line
// LiDAR data matching method based on graph theory", sec. 2.1), the features the graph
// matcher (libs/matching) builds its attributed graphs from:
//  1. median-filter the ranges (RangeMedianFilter);
//  2. jump points where neighbours are farther apart than k psi d (JumpDetector, k = 15);
//  3. turning angles summed over a 4-reading window (TurningAngle); convex endpoints where the
//     sum is < -pi/3, concave where > pi/3, with non-maximum suppression (EndpointDetector);
//  4. convex-convex segments: the readings between consecutive convex endpoints (jump points
//     included) of one run, fitted by least squares, kept when they are a line (residual
//     within the noise) and not an arc (InscribedAngleArcTest), merged with a collinear
//     neighbour across a convex endpoint, dropped when they have too few readings; never
//     across a jump (runs end at jumps);
//  5. concave-concave segments: the line between consecutive concave endpoints (across
//     occlusions), kept when more than 30 % of the valid readings between them lie on it.
// Concave-convex segments are not extracted (the paper does not either).
//
// Where the paper is silent or not robust enough, documented choices:
//  - the robust default measures the windowed turn over chords that span enough metres for
//    the range noise (TurningAngle.h); paperExact = true uses the paper's 4-tap sum;
//  - line and inlier tolerances are max(floor, z * sigma) with sigma the range noise;
//  - concave-concave lines are refitted by least squares on their inliers (the paper keeps
//    the line through the two endpoints, which carries their full noise); their ends are the
//    concave endpoints projected onto it.
// Segments are fitted on the unfiltered readings; endpoints are at filtered readings.
//
// Output (ScanFeatures, sensor frame): segments (Convex/Jump ends = convex-convex,
// Concave/Concave = concave-concave), endpoints (Convex, Concave, Jump); no corners.
#include <toposlam/config/Options.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/features/InscribedAngleArcTest.h>
#include <toposlam/features/JumpDetector.h>
#include <toposlam/features/LineFit.h>
#include <toposlam/features/RangeMedianFilter.h>
#include <toposlam/features/ScanPoints.h>
#include <toposlam/features/TurningAngle.h>

#include <vector>

namespace toposlam::features {

/// Section [SegmentExtractor] of config_ini/features.ini.
struct SegmentExtractorOptions : public config::Options {
    unsigned medianWindow = 3;        ///< readings (odd; 1 = off)
    double turnThreshold = M_PI / 3;  ///< rad: convex below -it, concave above it (paper)
    bool paperExact = false;          ///< the paper's 4-tap turning sum, no noise model
    double rangeNoiseStd = 0.01;      ///< m, when the scan does not state one
    bool useScanStdError = true;      ///< take the range noise from the scan's stdError
    double noiseSigmas = 3;           ///< z
    double minValidRange = 0;         ///< m
    JumpDetectorOptions jumps;
    unsigned minSegmentPoints = 5;       ///< readings of a convex-convex segment / concave inliers
    double maxLineResidual = 0.01;       ///< m, floor of the line tolerance (RMS)
    double mergeAngle = 5 * M_PI / 180;  ///< rad, collinear neighbours merge below it
    double concaveInlierRatio = 0.3;     ///< paper: > 30 % of the readings on the line
    double inlierDistance = 0.03;        ///< m, floor of "on the line"
    InscribedAngleArcTest arcTest;

    void declare(config::OptionsSchema& s) override;
};

class SegmentExtractor : public FeatureExtractor {
  public:
    SegmentExtractorOptions options;

    SegmentExtractor() = default;
    explicit SegmentExtractor(const SegmentExtractorOptions& o) : options(o) {}

    void extract(const mrpt::obs::CObservation2DRangeScan& scan, ScanFeatures& out) override;
    std::string name() const override { return options.paperExact ? "segments-paper" : "segments"; }
    void loadOptions(const mrpt::config::CConfigFileBase& cfg,
                     const std::string& section) override {
        options.loadFromConfigFile(cfg, section);
    }
    void dumpOptions(std::ostream& out) const override { options.dumpToTextStream(out); }

    /// The range noise (m) assumed for `scan` (0 in paperExact mode).
    double rangeNoise(const mrpt::obs::CObservation2DRangeScan& scan) const;

  private:
    struct Candidate {
        std::uint32_t from, to;  // endpoint readings (canonical)
        std::uint32_t fitBegin, fitEnd;
        EndpointType fromType, toType;
        LineFit fit;
    };
    void convexSegments(double sigma, ScanFeatures& out);
    void concaveSegments(double sigma, ScanFeatures& out);
    LineSegment makeSegment(const LineFit& fit, std::size_t firstReading, std::size_t lastReading,
                            const mrpt::math::TPoint2D& from, const mrpt::math::TPoint2D& to,
                            EndpointType fromType, EndpointType toType) const;

    ScanPoints raw_, filtered_;
    RangeMedianFilter median_;
    JumpDetector jumpDetector_;
    std::vector<PointRun> runs_;
    TurningAngle turning_;
    std::vector<Endpoint> endpoints_;  // canonical
    std::vector<Candidate> candidates_;
};

}  // namespace toposlam::features
