// Local lines of a dense, noisy laser (a Hokuyo URG-04LX: 682 beams over 240 deg, 2 cm range
// noise) in a 4 x 4 m room: the scan's noise is read off the scan itself, and lines reaching as
// far as that noise asks have the walls' normals, where two beams either side do not.
#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>
#include <toposlam/matching/LocalLine.h>
#include <toposlam/matching/PolarScan.h>
#include <toposlam/simulation/LaserModel.h>
#include <toposlam/simulation/PolygonWorld.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace toposlam {
namespace {

using mrpt::poses::CPose2D;

simulation::LaserModel urg04lx(double rangeNoise) {
    simulation::LaserModel laser;
    laser.beams = 682;
    laser.aperture = mrpt::DEG2RAD(240.0);
    laser.maxRange = 5.6;
    laser.rangeNoiseStd = rangeNoise;
    return laser;
}

/// The room's walls are x = +-2 and y = +-2; the sensor at its centre.
matching::PolarScan scanOfSquareRoom(double rangeNoise, unsigned seed) {
    simulation::PolygonWorld room;
    room.addPolygon({{-2, -2}, {2, -2}, {2, 2}, {-2, 2}});
    std::mt19937 rng(seed);
    matching::PolarScan scan;
    scan.assign(simulation::simulateScan(room, urg04lx(rangeNoise), CPose2D(), rng));
    return scan;
}

struct NormalErrors {
    double rmsDeg = 0;
    std::size_t lines = 0, readings = 0;
};

/// RMS angle between the fitted normals and the walls' (readings 30 cm or more from a corner).
NormalErrors normalErrors(const matching::PolarScan& scan, double reach) {
    double sum = 0;
    NormalErrors out;
    for (std::size_t b = 0; b < scan.size(); ++b) {
        if (!scan.valid(b))
            continue;
        const auto& p = scan.point(b);
        if (std::abs(std::abs(p.x) - 2) < 0.3 && std::abs(std::abs(p.y) - 2) < 0.3)
            continue;
        ++out.readings;
        const auto line = matching::fitLocalLine(scan, b, 0.3, reach);
        if (!line)
            continue;
        ++out.lines;
        // The wall the reading lies on: the nearer of |x| = 2 and |y| = 2.
        const bool onSide = std::abs(std::abs(p.x) - 2) < std::abs(std::abs(p.y) - 2);
        const double trueNx = onSide ? -std::copysign(1.0, p.x) : 0;
        const double trueNy = onSide ? 0 : -std::copysign(1.0, p.y);
        const double cosine = std::clamp(line->nx * trueNx + line->ny * trueNy, -1.0, 1.0);
        const double angle = std::acos(cosine);
        sum += angle * angle;
    }
    out.rmsDeg = mrpt::RAD2DEG(std::sqrt(sum / double(std::max<std::size_t>(out.lines, 1))));
    return out;
}

TEST(LocalLine, ReadsTheRangeNoiseOffTheScan) {
    // Range noise is along the beams; across the walls (what the estimate measures) it is
    // sigma x cos(incidence), and the incidence on this room's walls is 0-45 deg.
    for (const double sigma : {0.005, 0.01, 0.02}) {
        const double noise = matching::surfaceNoise(scanOfSquareRoom(sigma, 1));
        EXPECT_GT(noise, 0.6 * sigma) << sigma;
        EXPECT_LT(noise, 1.2 * sigma) << sigma;
    }
    EXPECT_LT(matching::surfaceNoise(scanOfSquareRoom(0, 1)), 1e-4);
}

TEST(LocalLine, ReachesAsFarAsTheNoiseAsksAndFindsTheWallsNormals) {
    const matching::PolarScan scan = scanOfSquareRoom(0.02, 2);
    const double reach = matching::localLineReach(matching::surfaceNoise(scan));
    EXPECT_GT(reach, 0.1);
    const NormalErrors wide = normalErrors(scan, reach), narrow = normalErrors(scan, 0);
    std::printf(
        "normals: +-2 beams %.1f deg RMS on %zu of %zu readings, reach %.3f m %.1f deg "
        "on %zu\n",
        narrow.rmsDeg, narrow.lines, narrow.readings, reach, wide.rmsDeg, wide.lines);
    // Two beams either side (2-5 cm here) give normals tens of degrees off; the noise's reach
    // gives its wall's normal within a few degrees to more readings (at 16 sigma a flat wall
    // passes the straightness test about half the time: the test still throws out what noise
    // bent, not the wall).
    EXPECT_GT(narrow.rmsDeg, 20.0);
    EXPECT_LT(wide.rmsDeg, 6.0);
    EXPECT_GT(wide.lines, 2 * narrow.lines);
}

TEST(LocalLine, KeepsTwoBeamsEitherSideOnACleanScan) {
    // Noise-free: the reach is nil and the neighbourhood the 2 beams it always was, so a
    // reading next to a corner still has its wall's line.
    const matching::PolarScan scan = scanOfSquareRoom(0, 3);
    EXPECT_LT(matching::localLineReach(matching::surfaceNoise(scan)), 1e-4);
    const NormalErrors clean = normalErrors(scan, 0);
    EXPECT_LT(clean.rmsDeg, 0.5);
    EXPECT_EQ(clean.lines, clean.readings);
}

}  // namespace
}  // namespace toposlam
