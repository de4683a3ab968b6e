#pragma once
// Scores extracted features against ScanGroundTruth (benchmark B1, BENCHMARKS.md):
//  - corners: a detection within matchRadius (0.10 m) of a ground-truth corner is a hit
//    (one-to-one, nearest pairs first); unmatched detections within matchRadius of a
//    "don't care" vertex are ignored, the rest are false alarms. precision = hits /
//    (detections - ignored), recall = hits / ground-truth corners. Position errors of the
//    hits (RMSE, also for corners within 8 m), corner angle errors (deg).
//  - segments: each ground-truth wall run is matched to the extracted segment whose beam span
//    overlaps it most (intersection over union >= 0.5, one-to-one); the endpoint error is the
//    distance from each end of the segment to the exact end of the visible wall.
// Accumulate over many scans, then read the summary.
#include <toposlam/featureeval/FeatureGroundTruth.h>
#include <toposlam/features/ScanFeatures.h>

#include <cstddef>
#include <vector>

namespace toposlam::featureeval {

struct FeatureScores {
    double matchRadius = 0.10;  ///< m
    double nearRange = 8.0;     ///< m, the "within 8 m" RMSE

    std::size_t groundTruthCorners = 0, detectedCorners = 0, hits = 0, ignored = 0;
    double sumSquaredError = 0, sumSquaredErrorNear = 0;
    std::size_t hitsNear = 0;
    double sumSquaredAngleError = 0, sumAbsAngleError = 0;  // deg^2, deg
    std::size_t groundTruthRuns = 0, matchedRuns = 0;
    double sumSquaredEndpointError = 0;  // m^2, two ends per matched run

    void add(const features::ScanFeatures& detected, const ScanGroundTruth& truth);

    double precision() const;         ///< [0,1]; 1 when nothing was detected
    double recall() const;            ///< [0,1]; 1 when there was nothing to find
    double positionRmse() const;      ///< m
    double positionRmseNear() const;  ///< m, ground truth within nearRange
    double angleRmseDeg() const;
    double angleMeanAbsDeg() const;
    double endpointRmse() const;   ///< m
    double segmentRecall() const;  ///< matched / ground-truth runs

  private:
    std::vector<std::size_t> order_;
    std::vector<char> usedTruth_, usedDetection_;
};

}  // namespace toposlam::featureeval
