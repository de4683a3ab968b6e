// Point-to-line ICP against a line map (the graph SLAM's scan registration): which directions
// it may move along.
#include <gtest/gtest.h>
#include <toposlam/matching/LineMap.h>
#include <toposlam/matching/PointToLineIcp.h>
#include <toposlam/matching/PolarScan.h>
#include <toposlam/simulation/LaserModel.h>
#include <toposlam/simulation/PolygonWorld.h>

#include <random>

namespace toposlam {
namespace {

using mrpt::poses::CPose2D;

// A corridor 3 m wide whose far end, 10 m ahead, is the only wall across it. Seen by a laser
// from its middle, the side walls reach out to 10 m: a turn moves those points by up to 10 m per
// radian, a step along the corridor moves only the end wall's. In radians the turn's eigenvalue
// is about 100 times that of the step, and ICP used to take the step for undetermined: it
// never moved along the corridor from where odometry put it.
TEST(PointToLineIcp, MovesAlongACorridorThatOnlyItsFarEndDetermines) {
    simulation::PolygonWorld corridor;
    corridor.addPolygon({{-2, -1.5}, {10, -1.5}, {10, 1.5}, {-2, 1.5}});
    simulation::LaserModel laser;  // 361 beams over 180 degrees, noise-free
    laser.maxRange = 30;
    std::mt19937 rng(1);
    const auto reference = simulation::simulateScan(corridor, laser, CPose2D(), rng);
    const CPose2D truth(0.15, 0.02, 0.01);
    const auto current = simulation::simulateScan(corridor, laser, truth, rng);

    matching::PolarScan referencePolar, currentPolar;
    referencePolar.assign(reference);
    currentPolar.assign(current);
    matching::LineMapOptions mapOptions;
    mapOptions.maxRange = laser.maxRange;
    matching::LineMap map(mapOptions);
    map.insertScan(referencePolar, CPose2D());

    matching::IcpOptions options;  // as the graph SLAM registers scans
    options.maxIterations = 30;
    options.maxDistance = 0.4;
    options.stride = 2;
    matching::PointToLineIcp icp;
    const matching::IcpResult r = icp.refineOnMap(map, currentPolar, CPose2D(), options);
    // Noise-free: the pose itself, to well below the map's 5 cm lookup cells.
    EXPECT_NEAR(r.pose.x(), truth.x(), 0.005) << r.pose;
    EXPECT_NEAR(r.pose.y(), truth.y(), 0.005) << r.pose;
    EXPECT_NEAR(r.pose.phi(), truth.phi(), 0.001) << r.pose;
}

}  // namespace
}  // namespace toposlam
