#pragma once
// Simulated scan pairs with exact ground truth for B2 (BENCHMARKS.md): two rooms (libs/
// simulation PolygonWorld), a 360-degree laser like the graph-matching paper's (360 beams,
// 1 deg, 20 m, range noise 1 cm), and every combination of a translation of 0.05 / 0.15 / 0.5
// / 1.0 m (random direction) with a rotation of 0 / 30 / 90 / 180 deg (random sign).
//   "sim-empty"      an L-shaped hall with niches and a pillar, nothing else;
//   "sim-cluttered"  the same hall furnished (tables, cabinets, boxes) with people-sized
//                    discs (r = 0.25 m) that all move by up to 0.5 m between the two scans.
// Robot poses are drawn uniformly in free space (>= 0.4 m from everything). The "odometry" of
// each pair is the truth with an error of exactly 1.0 m (random direction) and 30 deg
// (random sign): the guided test of the issue. Deterministic for a given seed.
#include <toposlam/matchingbench/ScanPair.h>

#include <cstdint>

namespace toposlam::matchingbench {

struct SimulatedPairsOptions {
    std::size_t pairsPerCase = 10;  ///< per room x offset x rotation
    std::uint32_t seed = 1;
    double rangeNoiseStd = 0.01;                      ///< m
    double guessTranslationError = 1.0;               ///< m
    double guessRotationError = 30.0 * M_PI / 180.0;  ///< rad
};

ScanPairs makeSimulatedPairs(const SimulatedPairsOptions& options = {});

}  // namespace toposlam::matchingbench
