// The accumulating feature map (FeatureMap, CScanFeaturesMap): scans simulated in exact
// polygon worlds, features extracted by the real extractor, inserted at their true poses; the
// merged map is checked against the world's own walls. Tolerances: 1 cm range noise on beams
// 0.5 deg apart gives lines good to a few millimetres and tenths of a degree; 3 cm / 1 deg
// leave room for that and nothing more.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/img/CImage.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/features/CObservationLaserFeatures.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/matching/CScanFeaturesMap.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "SyntheticScans.h"
#include "TestSupport.h"

using mrpt::math::TPoint2D;
using mrpt::poses::CPose2D;
using mrpt::poses::CPose3D;
using toposlam::features::EndpointType;
using namespace toposlam::matching;
namespace sim = toposlam::simulation;

namespace {

constexpr double kDeg = M_PI / 180;

sim::LaserModel noisyLaser() {
    auto laser = toposlam::test::fullCircleLaser(720, 20.0);
    laser.rangeNoiseStd = 0.01;
    return laser;
}

/// Poses inside asymmetricRoom() that together see every wall of the hall.
const std::vector<CPose2D>& roomPoses() {
    static const std::vector<CPose2D> poses = {{1.5, 1.0, 0.0},  {4.0, 1.2, 0.5}, {8.5, 2.8, 2.0},
                                               {4.5, 3.5, -1.0}, {3.0, 6.2, 0.3}, {1.0, 3.5, 1.2},
                                               {5.2, 2.0, 3.0},  {9.3, 0.5, -2.5}};
    return poses;
}

std::vector<mrpt::obs::CObservation2DRangeScan> roomScans(const sim::PolygonWorld& world,
                                                          const std::vector<CPose2D>& poses) {
    std::mt19937 rng(7);
    std::vector<mrpt::obs::CObservation2DRangeScan> scans;
    for (const CPose2D& p : poses)
        scans.push_back(sim::simulateScan(world, noisyLaser(), p, rng));
    return scans;
}

double distanceToWorld(const TPoint2D& p, const sim::PolygonWorld& world) {
    double best = 1e9;
    for (const sim::WallSegment& w : world.segments())
        best = std::min(best, pointToSegmentDistance(p, w.a, w.b));
    return best;
}

double lineAngleError(const MapSegment& s, const sim::WallSegment& w) {
    const double a = std::atan2(s.end.y - s.start.y, s.end.x - s.start.x);
    const double b = std::atan2(w.b.y - w.a.y, w.b.x - w.a.x);
    const double d = std::abs(std::remainder(a - b, M_PI));
    return d;
}

CScanFeaturesMap roomMap(const std::vector<CPose2D>& insertAt) {
    const auto world = toposlam::test::asymmetricRoom();
    const auto scans = roomScans(world, roomPoses());
    CScanFeaturesMap m("split-merge");
    for (std::size_t i = 0; i < scans.size(); ++i)
        EXPECT_TRUE(m.insertObservation(scans[i], CPose3D(insertAt[i])));
    return m;
}

}  // namespace

// Every confirmed segment lies on a wall; every wall of the hall has one segment along it
// (within 3 cm and 1 deg, covering most of it); no two confirmed segments are copies of
// each other (same facing, same line, overlapping): repeated observations were merged.
TEST(FeatureMap, AccumulatesEveryScanIntoOneMapOnTheWalls) {
    const auto world = toposlam::test::asymmetricRoom();
    const CScanFeaturesMap m = roomMap(roomPoses());
    const FeatureMap& map = m.featureMap();
    EXPECT_EQ(m.keyframes().size(), roomPoses().size());
    ASSERT_GE(map.confirmedSegments(), 10u) << m.asString();

    // Every point of every piece (10 cm apart) lies on a wall.
    for (const MapSegment& s : map.segments()) {
        if (!map.confirmed(s))
            continue;
        for (const SegmentPiece& p : s.pieces) {
            const int n = static_cast<int>(p.length() / 0.1) + 1;
            for (int k = 0; k <= n; ++k) {
                const TPoint2D q(p.start.x + (p.end.x - p.start.x) * k / n,
                                 p.start.y + (p.end.y - p.start.y) * k / n);
                EXPECT_LT(distanceToWorld(q, world), 0.03) << q.x << "," << q.y;
            }
        }
    }
    // The hall's 6 walls (the first polygon: its first 6 edges).
    for (std::size_t w = 0; w < 6; ++w) {
        const sim::WallSegment& wall = world.segments()[w];
        const double wallLength = std::hypot(wall.b.x - wall.a.x, wall.b.y - wall.a.y);
        double covered = 0;
        for (const MapSegment& s : map.segments()) {
            if (!map.confirmed(s) || lineAngleError(s, wall) > 1 * kDeg)
                continue;
            for (const SegmentPiece& p : s.pieces)
                if (pointToSegmentDistance(p.start, wall.a, wall.b) < 0.03 &&
                    pointToSegmentDistance(p.end, wall.a, wall.b) < 0.03)
                    covered = std::max(covered, p.length());
        }
        EXPECT_GT(covered, 0.6 * wallLength) << "hall wall " << w;
    }
    const auto& segs = map.segments();
    for (std::size_t i = 0; i < segs.size(); ++i) {
        for (std::size_t j = i + 1; j < segs.size(); ++j) {
            if (!map.confirmed(segs[i]) || !map.confirmed(segs[j]))
                continue;
            const double facing =
                std::abs(std::remainder(segs[i].facing() - segs[j].facing(), 2 * M_PI));
            const bool sameLine =
                facing < 2 * kDeg &&
                pointToSegmentDistance(segs[j].start, segs[i].start, segs[i].end) < 0.03 &&
                pointToSegmentDistance(segs[j].end, segs[i].start, segs[i].end) < 0.03;
            EXPECT_FALSE(sameLine) << "segments " << i << " and " << j << " duplicate a wall";
        }
    }
    // Corners: every confirmed one is a corner of the world (within 3 cm of two walls' ends).
    ASSERT_GE(map.confirmedCorners(), 5u);
    for (const MapPoint& c : map.corners()) {
        if (!map.confirmed(c))
            continue;
        double nearestVertex = 1e9;
        for (const sim::WallSegment& w : world.segments())
            nearestVertex =
                std::min(nearestVertex, std::hypot(w.a.x - c.position.x, w.a.y - c.position.y));
        EXPECT_LT(nearestVertex, 0.03) << c.position.x << "," << c.position.y;
    }
}

TEST(FeatureMap, RepeatedObservationsMergeAndConfirm) {
    const auto world = toposlam::test::asymmetricRoom();
    const auto scans = roomScans(world, {CPose2D(4.0, 1.2, 0.5)});
    CScanFeaturesMap m("split-merge");
    m.insertScan(scans[0], CPose2D(4.0, 1.2, 0.5));
    const std::size_t n = m.featureMap().segments().size();
    ASSERT_GT(n, 3u);
    EXPECT_EQ(m.featureMap().confirmedSegments(), 0u) << "seen once: not confirmed yet";
    m.insertScan(scans[0], CPose2D(4.0, 1.2, 0.5));
    EXPECT_EQ(m.featureMap().segments().size(), n) << "the same scan again adds nothing new";
    EXPECT_EQ(m.featureMap().confirmedSegments(), n);
    for (const MapSegment& s : m.featureMap().segments())
        EXPECT_EQ(s.observations, 2u);
}

// A 0.1 m wall seen from both sides: two faces, facing opposite ways, 0.1 m apart.
TEST(FeatureMap, TheTwoFacesOfAThinWallStaySeparate) {
    sim::PolygonWorld world;
    world.addPolygon({{-3, -0.05}, {3, -0.05}, {3, 0.05}, {-3, 0.05}});
    std::mt19937 rng(3);
    CScanFeaturesMap m("split-merge");
    for (const CPose2D& p :
         {CPose2D(-1, 1.5, 0), CPose2D(1, 1.5, 0), CPose2D(-1, -1.5, 0), CPose2D(1, -1.5, 0)})
        m.insertScan(sim::simulateScan(world, noisyLaser(), p, rng), p);
    int north = 0, south = 0;
    for (const MapSegment& s : m.featureMap().segments()) {
        if (!m.featureMap().confirmed(s) || s.length() < 3)
            continue;
        const double y = 0.5 * (s.start.y + s.end.y);
        if (std::abs(s.facing() - M_PI / 2) < 2 * kDeg && std::abs(y - 0.05) < 0.01)
            ++north;
        if (std::abs(s.facing() + M_PI / 2) < 2 * kDeg && std::abs(y + 0.05) < 0.01)
            ++south;
    }
    EXPECT_EQ(north, 1);
    EXPECT_EQ(south, 1);
}

// Two collinear walls with a 0.9 m doorway between them: two pieces, none across the door.
TEST(FeatureMap, CollinearWallsAcrossADoorStaySeparate) {
    sim::PolygonWorld world;
    world.addSegment({-4, 2}, {-0.45, 2});
    world.addSegment({0.45, 2}, {4, 2});
    std::mt19937 rng(4);
    CScanFeaturesMap m("split-merge");
    for (const CPose2D& p : {CPose2D(-1, 0, 0.3), CPose2D(1, 0, 0.1), CPose2D(0, 0.5, 1.0)})
        m.insertScan(sim::simulateScan(world, noisyLaser(), p, rng), p);
    EXPECT_EQ(m.featureMap().confirmedPieces(), 2u);
    for (const MapSegment& s : m.featureMap().segments())
        for (const SegmentPiece& p : s.pieces)
            EXPECT_FALSE(std::min(p.start.x, p.end.x) < -0.3 && std::max(p.start.x, p.end.x) > 0.3)
                << "a piece spans the doorway: " << p.start.x << " .. " << p.end.x;
}

// A scan looking along a wall at a grazing angle steps over a door without a beam through it:
// its segment bridges the door. The line is then shared, but the door stays open, because the
// scans that faced the wall covered it densely on both sides and not at all in between.
TEST(FeatureMap, AGrazingViewDoesNotCloseADoor) {
    sim::PolygonWorld world;
    world.addSegment({-4, 2}, {-0.45, 2});
    world.addSegment({0.45, 2}, {4, 2});
    std::mt19937 rng(4);
    FeatureMap map;
    const auto extractor = toposlam::features::makeFeatureExtractor("split-merge");
    toposlam::features::ScanFeatures f;
    for (const CPose2D& p : {CPose2D(-2, 0.5, 1.3), CPose2D(2, 0.5, 1.8), CPose2D(-2.2, 0.3, 1.5),
                             CPose2D(2.2, 0.3, 1.6)}) {
        extractor->extract(sim::simulateScan(world, noisyLaser(), p, rng), f);
        map.insert(f, p);
    }
    ASSERT_EQ(map.confirmedPieces(), 2u);
    // The grazing views, three times: one segment of 8 beams from x = -3.8 to 3.8 (sensor at
    // (-6, 1.9) looking along +x; the door is between beams).
    toposlam::features::ScanFeatures grazing;
    toposlam::features::LineSegment s;
    s.start = {2.2, 0.1};
    s.end = {9.8, 0.1};
    s.firstBeam = 100;
    s.lastBeam = 107;
    grazing.segments.push_back(s);
    for (int k = 0; k < 3; ++k)
        map.insert(grazing, CPose2D(-6, 1.9, 0));
    std::size_t lines = 0;
    for (const MapSegment& line : map.segments()) {
        if (!map.confirmed(line))
            continue;
        ++lines;
        for (const SegmentPiece& p : line.pieces)
            EXPECT_FALSE(std::min(p.start.x, p.end.x) < -0.3 && std::max(p.start.x, p.end.x) > 0.3)
                << "a piece spans the doorway: " << p.start.x << " .. " << p.end.x;
    }
    EXPECT_EQ(lines, 1u) << "the bridging view joined both walls into one line";
    EXPECT_EQ(map.confirmedPieces(), 2u);
}

// The SLAM back-end path: insert at drifting odometry poses, then move the keyframes to the
// corrected poses: the map is exactly the one built at the corrected poses directly.
TEST(CScanFeaturesMap, RebuildsFromKeyframesWhenThePosesChange) {
    std::vector<CPose2D> drifted;
    for (std::size_t i = 0; i < roomPoses().size(); ++i)
        drifted.push_back(roomPoses()[i] + CPose2D(0.05 * i, -0.03 * i, 0.01 * i));
    CScanFeaturesMap m = roomMap(drifted);
    const CScanFeaturesMap direct = roomMap(roomPoses());
    m.updateKeyframePoses(roomPoses());

    const auto& a = m.featureMap().segments();
    const auto& b = direct.featureMap().segments();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_NEAR(a[i].start.x, b[i].start.x, 1e-9);
        EXPECT_NEAR(a[i].end.y, b[i].end.y, 1e-9);
        EXPECT_EQ(a[i].observations, b[i].observations);
    }
    EXPECT_EQ(m.featureMap().corners().size(), direct.featureMap().corners().size());

    // rebuild() from keyframes given by the caller does the same.
    CScanFeaturesMap r("split-merge");
    r.rebuild(m.keyframes());
    EXPECT_EQ(r.featureMap().segments().size(), b.size());
    EXPECT_THROW(m.updateKeyframePoses({CPose2D()}), std::invalid_argument);
}

// source = features: CObservationLaserFeatures (what toposlam-annotate-features stores) build
// the same map as their scans; scans are then ignored (an annotated log has both).
TEST(CScanFeaturesMap, StoredFeatureObservationsBuildTheSameMap) {
    const auto world = toposlam::test::asymmetricRoom();
    const auto scans = roomScans(world, roomPoses());
    const auto extractor = toposlam::features::makeFeatureExtractor("split-merge");
    CScanFeaturesMap fromScans("split-merge"), fromFeatures("split-merge");
    fromFeatures.insertionOptions.source = CScanFeaturesMap::Source::Features;
    for (std::size_t i = 0; i < scans.size(); ++i) {
        const CPose3D pose(roomPoses()[i]);
        toposlam::features::CObservationLaserFeatures f;
        extractor->extract(scans[i], f.features);
        f.sensorPose = scans[i].sensorPose;
        fromScans.insertObservation(scans[i], pose);
        EXPECT_FALSE(fromFeatures.insertObservation(scans[i], pose)) << "scans are ignored";
        EXPECT_TRUE(fromFeatures.insertObservation(f, pose));
    }
    EXPECT_EQ(fromFeatures.featureMap().segments().size(),
              fromScans.featureMap().segments().size());
    EXPECT_EQ(fromFeatures.featureMap().confirmedCorners(),
              fromScans.featureMap().confirmedCorners());
    EXPECT_FALSE(fromScans.insertObservation(mrpt::obs::CObservationOdometry(), CPose3D()));
}

// The documented log-likelihood on a case worked by hand: one wall y = 2 seen straight on by
// a 90 deg laser; every point lies d off the wall when the pose is shifted by d across it, so
// log L = -d^2 / sigma_dist, and -max_corr_distance^2 / sigma_dist once d passes it.
TEST(CScanFeaturesMap, LikelihoodIsMrptsPointsMapFormulaOnWallDistances) {
    sim::PolygonWorld world;
    world.addSegment({-10, 2}, {10, 2});
    sim::LaserModel laser;
    laser.beams = 181;
    laser.aperture = M_PI / 2;
    std::mt19937 rng(1);
    const CPose2D pose(0, 0, M_PI / 2);
    const auto scan = sim::simulateScan(world, laser, pose, rng);
    CScanFeaturesMap m("split-merge");
    EXPECT_DOUBLE_EQ(m.computeObservationLikelihood(scan, CPose3D(pose)), 0.0) << "empty map";
    m.insertScan(scan, pose);
    m.insertScan(scan, pose);
    ASSERT_EQ(m.featureMap().confirmedSegments(), 1u);
    const double sigma = m.likelihoodOptions.sigma_dist;
    EXPECT_NEAR(m.computeObservationLikelihood(scan, CPose3D(pose)), 0.0, 1e-6);
    EXPECT_NEAR(m.computeObservationLikelihood(scan, CPose3D(CPose2D(0, 0.05, M_PI / 2))),
                -0.05 * 0.05 / sigma, 1e-6);
    const double maxD = m.likelihoodOptions.max_corr_distance;
    EXPECT_NEAR(m.computeObservationLikelihood(scan, CPose3D(CPose2D(0, 2 + 4 * maxD, M_PI / 2))),
                -maxD * maxD / sigma, 1e-6);
    EXPECT_TRUE(m.canComputeObservationLikelihood(scan));
    EXPECT_FALSE(m.canComputeObservationLikelihood(mrpt::obs::CObservationOdometry()));
}

// In the room: the true pose is more likely than any pose 10 cm or 3 deg off, for scans and
// for their stored features alike.
TEST(CScanFeaturesMap, TheTruePoseIsTheMostLikely) {
    const auto world = toposlam::test::asymmetricRoom();
    const CScanFeaturesMap m = roomMap(roomPoses());
    std::mt19937 rng(11);
    const CPose2D truth(6.0, 2.5, 0.7);
    const auto scan = sim::simulateScan(world, noisyLaser(), truth, rng);
    toposlam::features::CObservationLaserFeatures f;
    toposlam::features::makeFeatureExtractor("split-merge")->extract(scan, f.features);
    const double atTruthScan = m.computeObservationLikelihood(scan, CPose3D(truth));
    const double atTruthFeatures = m.computeObservationLikelihood(f, CPose3D(truth));
    for (const CPose2D& off : {CPose2D(0.1, 0, 0), CPose2D(0, -0.1, 0), CPose2D(0, 0, 3 * kDeg),
                               CPose2D(0, 0, -3 * kDeg)}) {
        EXPECT_GT(atTruthScan, m.computeObservationLikelihood(scan, CPose3D(truth + off)));
        EXPECT_GT(atTruthFeatures, m.computeObservationLikelihood(f, CPose3D(truth + off)));
    }
}

// A laser mounted upside down (MRPT: a roll of 180 deg; its readings sweep the other way)
// builds the same map and gives the same likelihoods as the upright laser it mirrors.
TEST(CScanFeaturesMap, AnUpsideDownLaserMapsAsTheUprightOne) {
    const auto world = toposlam::test::asymmetricRoom();
    const auto scans = roomScans(world, roomPoses());
    CScanFeaturesMap upright("split-merge"), upsideDown("split-merge");
    std::vector<mrpt::obs::CObservation2DRangeScan> flipped;
    for (std::size_t i = 0; i < scans.size(); ++i) {
        auto f = scans[i];
        f.rightToLeft = !f.rightToLeft;
        f.sensorPose = CPose3D(0, 0, 0.3, 0, 0, M_PI);
        flipped.push_back(f);
        upright.insertObservation(scans[i], CPose3D(roomPoses()[i]));
        upsideDown.insertObservation(f, CPose3D(roomPoses()[i]));
    }
    const auto& a = upright.featureMap().segments();
    const auto& b = upsideDown.featureMap().segments();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_NEAR(a[i].start.x, b[i].start.x, 1e-6);
        EXPECT_NEAR(a[i].start.y, b[i].start.y, 1e-6);
        EXPECT_NEAR(a[i].end.x, b[i].end.x, 1e-6);
        EXPECT_NEAR(a[i].end.y, b[i].end.y, 1e-6);
    }
    const CPose3D off(CPose2D(6.0, 2.5, 0.7));
    EXPECT_NEAR(upright.computeObservationLikelihood(scans[2], off),
                upright.computeObservationLikelihood(flipped[2], off), 1e-9);
}

TEST(CScanFeaturesMap, SerializesKeyframesOptionsAndTheLastScan) {
    CScanFeaturesMap m = roomMap(roomPoses());
    m.insertionOptions.merge.mergeGap = 0.3;  // a non-default option travels too
    m.likelihoodOptions.decimation = 3;
    mrpt::io::CMemoryStream buffer;
    mrpt::serialization::archiveFrom(buffer) << m;
    buffer.Seek(0);
    const auto back = std::dynamic_pointer_cast<CScanFeaturesMap>(
        mrpt::serialization::archiveFrom(buffer).ReadObject());
    ASSERT_TRUE(back);
    EXPECT_EQ(back->keyframes().size(), m.keyframes().size());
    EXPECT_DOUBLE_EQ(back->insertionOptions.merge.mergeGap, 0.3);
    EXPECT_EQ(back->likelihoodOptions.decimation, 3u);
    ASSERT_TRUE(back->hasScan());
    EXPECT_EQ(back->features().segments.size(), m.features().segments.size());
    CScanFeaturesMap expected("split-merge");
    expected.insertionOptions.merge.mergeGap = 0.3;
    expected.rebuild(m.keyframes());
    EXPECT_EQ(back->featureMap().segments().size(), expected.featureMap().segments().size());
    EXPECT_EQ(back->featureMap().confirmedCorners(), expected.featureMap().confirmedCorners());
}

TEST(CScanFeaturesMap, IniMapDefinitionsSetEveryOptionAndRejectBadValues) {
    mrpt::config::CConfigFileMemory ini;
    ini.write("map", "scanFeaturesMap_count", 1);
    ini.write("map_scanFeaturesMap_00_creationOpts", "extractor", "corners");
    ini.write("map_scanFeaturesMap_00_insertOpts", "source", "features");
    ini.write("map_scanFeaturesMap_00_insertOpts", "merge_angle_deg", 3.0);
    ini.write("map_scanFeaturesMap_00_insertOpts", "min_observations", 3);
    ini.write("map_scanFeaturesMap_00_likelihoodOpts", "sigma_dist", 0.01);
    ini.write("map_scanFeaturesMap_00_likelihoodOpts", "decimation", 2);
    mrpt::maps::TSetOfMetricMapInitializers defs;
    defs.loadFromConfigFile(ini, "map");
    mrpt::maps::CMultiMetricMap maps;
    maps.setListOfMaps(defs);
    const auto m = maps.mapByClass<CScanFeaturesMap>();
    ASSERT_TRUE(m);
    EXPECT_EQ(m->extractor(), "corners");
    EXPECT_EQ(m->insertionOptions.source, CScanFeaturesMap::Source::Features);
    EXPECT_NEAR(m->insertionOptions.merge.mergeAngle, 3 * kDeg, 1e-12);
    EXPECT_EQ(m->insertionOptions.merge.minObservations, 3u);
    EXPECT_DOUBLE_EQ(m->likelihoodOptions.sigma_dist, 0.01);
    EXPECT_EQ(m->likelihoodOptions.decimation, 2u);

    for (const auto& [key, value] :
         std::vector<std::pair<std::string, std::string>>{{"merge_distance", "-0.1"},
                                                          {"merge_angle_deg", "nan"},
                                                          {"source", "lasers"},
                                                          {"min_observations", "0"},
                                                          {"mergeGap", "0.3"}}) {
        mrpt::config::CConfigFileMemory bad;
        bad.write("map", "scanFeaturesMap_count", 1);
        bad.write("map_scanFeaturesMap_00_insertOpts", key, value);
        mrpt::maps::TSetOfMetricMapInitializers badDefs;
        EXPECT_THROW(badDefs.loadFromConfigFile(bad, "map"), std::exception) << key << "=" << value;
    }
}

TEST(CScanFeaturesMap, SavesTextFilesAndAPictureAndDrawsIn3D) {
    const CScanFeaturesMap m = roomMap(roomPoses());
    toposlam::test::TempDir dir;
    const std::string prefix = dir.file("fm");
    m.saveMetricMapRepresentationToFile(prefix);
    std::ifstream segments(prefix + "_segments.txt");
    std::size_t lines = 0;
    for (std::string line; std::getline(segments, line);)
        lines += line.empty() || line[0] == '#' ? 0 : 1;
    EXPECT_EQ(lines, m.featureMap().confirmedPieces());
    EXPECT_TRUE(std::filesystem::exists(prefix + "_corners.txt"));
    EXPECT_TRUE(std::filesystem::exists(prefix + "_endpoints.txt"));
    mrpt::img::CImage png;
    ASSERT_TRUE(png.loadFromFile(prefix + ".png"));
    // 10 m x 7 m hall + 0.5 m margins at 2 cm per pixel.
    EXPECT_NEAR(png.getWidth(), 550, 5);
    EXPECT_NEAR(png.getHeight(), 400, 5);

    mrpt::opengl::CSetOfObjects scene;
    m.getVisualizationInto(scene);
    std::size_t segmentLines = 0, cornerPoints = 0;
    for (const auto& obj : scene) {
        if (const auto l = std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(obj))
            segmentLines += l->size();
        if (const auto c = std::dynamic_pointer_cast<mrpt::opengl::CPointCloudColoured>(obj);
            c && c->getPointSize() > 6)
            cornerPoints += c->size();
    }
    EXPECT_EQ(segmentLines, m.featureMap().confirmedPieces());
    EXPECT_EQ(cornerPoints, m.featureMap().confirmedCorners());
}

// RawLogViewer's "Raw map" dialog, without the GUI: the configuration text that
// share/doc/mrpt-tools.md tells the user to type into the dialog, read the way the dialog
// reads it (CConfigFileMemory, section "map"), and the observations inserted as the dialog
// inserts an observations-format rawlog (each CObservationOdometry sets the pose, every
// observation is inserted at it). "Preview map in 3D" shows getVisualization().
TEST(CScanFeaturesMap, RawLogViewersRawMapDialogBuildsAndDrawsIt) {
    const char* dialogText =
        "[map]\n"
        "pointsMap_count=0\n"
        "scanFeaturesMap_count=1\n"
        "[map_scanFeaturesMap_00_creationOpts]\n"
        "extractor=split-merge\n";
    mrpt::config::CConfigFileMemory cfg(dialogText);
    mrpt::maps::TSetOfMetricMapInitializers defs;
    defs.loadFromConfigFile(cfg, "map");
    mrpt::maps::CMultiMetricMap theMap;
    theMap.setListOfMaps(defs);
    ASSERT_EQ(theMap.maps.size(), 1u);

    const auto world = toposlam::test::asymmetricRoom();
    const auto scans = roomScans(world, roomPoses());
    for (std::size_t i = 0; i < scans.size(); ++i) {
        mrpt::obs::CObservationOdometry odometry;
        odometry.odometry = roomPoses()[i];
        const CPose3D curPose(odometry.odometry);
        theMap.insertObservation(odometry, curPose);
        theMap.insertObservation(scans[i], curPose);
    }
    const auto m = theMap.mapByClass<CScanFeaturesMap>();
    ASSERT_TRUE(m);
    EXPECT_EQ(m->keyframes().size(), scans.size());
    const auto scene = theMap.getVisualization();
    std::size_t lines = 0;
    for (const auto& obj : *scene)
        if (const auto l = std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(obj))
            lines += l->size();
    EXPECT_EQ(lines, m->featureMap().confirmedPieces());
    EXPECT_GE(lines, 10u);
}
