#pragma once
// The graph matcher as an MRPT map-alignment algorithm: AlignPDF(m1, m2, guess) returns the
// pose of map m2 relative to map m1 (MRPT's convention) as a CPosePDFGaussian whose covariance
// comes from the point-to-line refinement. Both maps must be CScanFeaturesMap (a scan each,
// inserted at any robot pose, with any sensor pose: the result is corrected for both).
//  - options.useGuess = true: the guess's mean prunes candidate segment pairs (tracking with
//    odometry; its covariance widens the windows to 3 sigma when that is larger);
//    false: guess-free matching (loop closure, relocalisation), the guess is ignored.
//  - When the match is not reliable (GraphScanMatcher's decision: poor fit, degenerate,
//    ambiguous, too few features), the returned PDF has the best pose found (or the guess)
//    with a covariance of unreliableVariance on every axis, so that a consumer fusing it
//    gives it no weight; pass a TGraphMatcherAlignmentResult as outInfo to read the status.
// Each map contributes its LAST inserted scan and that scan's features (a map built with
// setScan() holds exactly one). Align3DPDF works on the 2D part of the poses.
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/slam/CMetricMapsAlignmentAlgorithm.h>
#include <toposlam/matching/GraphScanMatcher.h>

namespace toposlam::mrptslam {

/// outInfo of CGraphMatcherAlignment: the matcher's full result.
struct TGraphMatcherAlignmentResult : public mrpt::slam::TMetricMapAlignmentResult {
    matching::MatchResult match;
    /// match.pose converted into map frames: pose of m2 relative to m1.
    mrpt::poses::CPose2D mapPose;
};

class CGraphMatcherAlignment : public mrpt::slam::CMetricMapsAlignmentAlgorithm {
  public:
    /// Section [GraphScanMatcher] of config_ini/graph-matcher.ini: the matcher's keys plus
    /// use_guess and unreliable_variance.
    struct Options : public config::Options {
        matching::GraphMatcherOptions matcher;
        bool useGuess = true;
        double unreliableVariance = 1e4;  ///< m^2 and rad^2
        void declare(config::OptionsSchema& s) override;
    } options;

    CGraphMatcherAlignment();

    mrpt::poses::CPosePDF::Ptr AlignPDF(
        const mrpt::maps::CMetricMap* m1, const mrpt::maps::CMetricMap* m2,
        const mrpt::poses::CPosePDFGaussian& initialEstimationPDF,
        mrpt::optional_ref<mrpt::slam::TMetricMapAlignmentResult> outInfo = std::nullopt) override;

    mrpt::poses::CPose3DPDF::Ptr Align3DPDF(
        const mrpt::maps::CMetricMap* m1, const mrpt::maps::CMetricMap* m2,
        const mrpt::poses::CPose3DPDFGaussian& initialEstimationPDF,
        mrpt::optional_ref<mrpt::slam::TMetricMapAlignmentResult> outInfo = std::nullopt) override;

  private:
    matching::GraphScanMatcher matcher_;
};

}  // namespace toposlam::mrptslam
