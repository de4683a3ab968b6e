#pragma once
// The data of benchmark B1: scans of random furnished rooms (SyntheticRooms.h) taken by a
// given laser with a given range noise, each with its exact ground truth
// (FeatureGroundTruth.h); and the scoring of an extractor over them. Scenes and noise come
// from separate seeded generators, so every laser and noise level sees the same rooms and
// poses, and every run of the benchmark the same scans.
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <toposlam/featureeval/FeatureGroundTruth.h>
#include <toposlam/featureeval/FeatureMetrics.h>
#include <toposlam/featureeval/SyntheticRooms.h>
#include <toposlam/features/FeatureExtractor.h>

#include <string>
#include <vector>

namespace toposlam::featureeval {

struct LaserSetup {
    std::size_t beams = 361;
    double aperture = M_PI;  ///< rad
    double maxRange = 30;    ///< m
    /// "1081 x 270 deg"
    std::string name() const;
};

struct SimulatedScan {
    mrpt::obs::CObservation2DRangeScan scan;  ///< stdError = the simulated range noise
    ScanGroundTruth truth;
};

/// `rooms` random rooms (poses included) from `seed`.
std::vector<SyntheticScene> makeScenes(int rooms, unsigned seed,
                                       const SyntheticRoomOptions& options = {});

/// One scan per pose of every scene; Gaussian range noise sigma (m) from `noiseSeed`.
std::vector<SimulatedScan> simulateScans(const std::vector<SyntheticScene>& scenes,
                                         const LaserSetup& laser, double sigma, unsigned noiseSeed,
                                         const GroundTruthOptions& truth = {});

/// Runs the extractor on every scan and scores it.
FeatureScores scoreExtractor(features::FeatureExtractor& extractor,
                             const std::vector<SimulatedScan>& scans);

/// Distances between the corners two extractors find on the same scans (each corner of `a`
/// paired with the nearest corner of `b` within `radius`): how far, e.g., the two-point fit
/// puts corners from least squares.
struct CornerAgreement {
    std::size_t pairs = 0;
    double mean = 0, p95 = 0, max = 0;  ///< m
};
CornerAgreement compareCorners(features::FeatureExtractor& a, features::FeatureExtractor& b,
                               const std::vector<SimulatedScan>& scans, double radius = 0.1);

}  // namespace toposlam::featureeval
