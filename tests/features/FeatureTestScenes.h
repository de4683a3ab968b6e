#pragma once
// Small exact scenes for the feature tests, built on the project's own simulator.
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/featureeval/SyntheticRooms.h>
#include <toposlam/features/ScanFeatures.h>
#include <toposlam/simulation/LaserModel.h>
#include <toposlam/simulation/PolygonWorld.h>

#include <random>
#include <vector>

namespace toposlam::test {

/// A rectangular room [x0,x1] x [y0,y1] with one box; counter-clockwise polygons.
inline featureeval::SyntheticScene roomWithBox() {
    featureeval::SyntheticScene s;
    s.polygons.push_back({{-3, -2}, {5, -2}, {5, 4}, {-3, 4}});
    s.polygons.push_back({{2, 0.5}, {3, 0.5}, {3, 1.3}, {2, 1.3}});
    return s;
}

inline mrpt::obs::CObservation2DRangeScan scanOf(const featureeval::SyntheticScene& scene,
                                                 const mrpt::poses::CPose2D& pose,
                                                 std::size_t beams, double aperture,
                                                 double sigma = 0, unsigned seed = 1) {
    simulation::LaserModel laser;
    laser.beams = beams;
    laser.aperture = aperture;
    laser.rangeNoiseStd = sigma;
    laser.maxRange = 30;
    std::mt19937 rng(seed);
    return simulation::simulateScan(scene.world(), laser, pose, rng);
}

/// The same scan with its beams in the opposite order (a left-to-right scanner).
inline mrpt::obs::CObservation2DRangeScan reversed(const mrpt::obs::CObservation2DRangeScan& s) {
    mrpt::obs::CObservation2DRangeScan r = s;
    r.rightToLeft = !s.rightToLeft;
    const std::size_t n = s.getScanSize();
    for (std::size_t i = 0; i < n; ++i) {
        r.setScanRange(i, s.getScanRange(n - 1 - i));
        r.setScanRangeValidity(i, s.getScanRangeValidity(n - 1 - i));
    }
    return r;
}

/// Distance (m) from p to the nearest of `points` (infinity if none).
inline double nearest(const mrpt::math::TPoint2D& p,
                      const std::vector<mrpt::math::TPoint2D>& points) {
    double best = HUGE_VAL;
    for (const auto& q : points)
        best = std::min(best, std::hypot(p.x - q.x, p.y - q.y));
    return best;
}

}  // namespace toposlam::test
