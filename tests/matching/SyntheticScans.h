#pragma once
// Test scans with exact segments: a scan simulated in a PolygonWorld, and its segments taken
// from the world's geometry (every run of consecutive beams that hit the same wall becomes a
// segment on that wall's exact line). No extractor is involved, so matcher tests see ideal
// features and test the matcher alone.
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/features/ScanFeatures.h>
#include <toposlam/matching/PolarScan.h>
#include <toposlam/simulation/LaserModel.h>
#include <toposlam/simulation/PolygonWorld.h>

#include <random>

namespace toposlam::test {

struct SyntheticScan {
    mrpt::obs::CObservation2DRangeScan observation;
    matching::PolarScan polar;
    features::ScanFeatures features;
};

/// A 360-degree laser (no duplicated beam), noise-free unless changed.
simulation::LaserModel fullCircleLaser(std::size_t beams = 360, double maxRange = 20.0);

/// Simulates the scan at `robotPose` and derives its segments from the walls it saw (runs of
/// at least `minBeams` beams). The laser's sensorPose must be the identity.
SyntheticScan simulateWithSegments(const simulation::PolygonWorld& world,
                                   const simulation::LaserModel& laser,
                                   const mrpt::poses::CPose2D& robotPose, std::size_t minBeams = 4);

/// A non-symmetric room (an L-shaped hall with a pillar box and a table) for matching tests.
simulation::PolygonWorld asymmetricRoom();

}  // namespace toposlam::test
