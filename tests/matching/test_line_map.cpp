// LineMap's lookup: the point it returns against a brute-force search, fusing, and a grid that
// stays small when readings lie far apart.
#include <gtest/gtest.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/matching/LineMap.h>
#include <toposlam/matching/PolarScan.h>

#include <cmath>
#include <random>
#include <vector>

namespace toposlam {
namespace {

using matching::LineMap;
using matching::LineMapPoint;

LineMapPoint pointAt(float x, float y, float nx = 1, float ny = 0) {
    LineMapPoint p;
    p.x = x, p.y = y, p.nx = nx, p.ny = ny, p.weight = 1;
    return p;
}

double distance(const LineMapPoint& p, double x, double y) {
    return std::hypot(p.x - x, p.y - y);
}

// The lookup answers with the point nearest to the query's cell centre, which is at most half a
// cell diagonal from the query: so the answer is within one diagonal of the true nearest, and
// there is an answer whenever a point lies within radius minus half a diagonal.
void expectLookupMatchesBruteForce(const LineMap& map, double x, double y) {
    const double halfDiagonal = map.options().resolution * std::sqrt(0.5);
    double best = INFINITY;
    for (const LineMapPoint& p : map.points())
        best = std::min(best, distance(p, x, y));
    const LineMapPoint* found = map.nearest(x, y);
    if (found == nullptr) {
        EXPECT_GT(best, map.options().radius - halfDiagonal) << "at " << x << ", " << y;
        return;
    }
    EXPECT_LE(distance(*found, x, y), map.options().radius + halfDiagonal);
    EXPECT_LE(distance(*found, x, y), best + 2 * halfDiagonal) << "at " << x << ", " << y;
}

// Points scattered over two areas 150 m apart (as an 80 m laser sees a hall), inserted one by one
// so that the grid grows in every direction: every lookup agrees with a brute-force search.
TEST(LineMap, FindsTheNearestPointWhereverTheGridGrew) {
    LineMap map;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> near(-4, 4), offset(-0.5f, 0.5f);
    for (int i = 0; i < 400; ++i) {
        const float far = (i % 2 == 0) ? 0.0f : 150.0f;
        // Normals differ point to point, so nothing is fused and every point stays.
        const float a = float(i);
        const float y = -far + near(rng), x = far + near(rng);  // one draw per statement
        map.insert(pointAt(x, y, std::cos(a), std::sin(a)));
    }
    ASSERT_GT(map.size(), 300u);
    for (int q = 0; q < 4000; ++q) {
        const float far = (q % 2 == 0) ? 0.0f : 150.0f;
        const float yNear = near(rng), yOffset = offset(rng);
        const float xNear = near(rng), xOffset = offset(rng);
        expectLookupMatchesBruteForce(map, far + xNear + xOffset, -far + yNear + yOffset);
    }
    // Between the two areas, far from every point: nothing.
    EXPECT_EQ(map.nearest(75, -75), nullptr);
    EXPECT_EQ(map.nearest(-1000, 1000), nullptr);
}

// Two readings 150 m apart need lookup cells around each, not a grid spanning both: a dense
// 5 cm grid over that square would be 9 million cells.
TEST(LineMap, KeepsLookupCellsOnlyNearItsPoints) {
    LineMap map;
    map.insert(pointAt(0, 0));
    map.insert(pointAt(150, 150));
    ASSERT_EQ(map.size(), 2u);
    // Each point's 0.4 m disc spans at most 2 x 2 tiles of 32 x 32 cells.
    EXPECT_LE(map.lookupCells(), 8u * 32u * 32u);
    EXPECT_NE(map.nearest(150.1, 149.9), nullptr);
    EXPECT_EQ(map.nearest(75, 75), nullptr);
}

// A second observation of the same surface close by is averaged into the point already there.
TEST(LineMap, FusesRepeatedObservationsOfOneSurface) {
    LineMap map;
    map.insert(pointAt(1.0f, 2.0f));
    map.insert(pointAt(1.02f, 2.0f));
    ASSERT_EQ(map.size(), 1u);
    EXPECT_NEAR(map.points()[0].x, 1.01, 1e-6);
    EXPECT_FLOAT_EQ(map.points()[0].weight, 2);
    // The opposite side of a thin wall (normal reversed) stays a point of its own.
    map.insert(pointAt(1.02f, 2.0f, -1, 0));
    EXPECT_EQ(map.size(), 2u);
}

// Views: a wall seen from two poses 0.3 m apart is confirmed; a disc that keeps 1 m ahead of
// the sensor (a person walking along) is somewhere else in each scan and is not; and readings
// of one scan, however close, count once.
TEST(LineMap, CountsTheScansThatSawEachPoint) {
    using matching::SurfacePoint;
    const auto scanAt = [](double sensorX) {
        std::vector<SurfacePoint> points;
        for (double x = -1; x <= 1.5; x += 0.01)  // the wall y = 1 (dense: readings fuse)
            points.push_back({x - sensorX, 1, 0, -1});
        for (double a = -1.0; a <= 1.0; a += 0.05) {  // the disc's face towards the sensor
            const double cx = 1.25 - 0.25 * std::cos(a), cy = 0.25 * std::sin(a);
            points.push_back({cx, cy, -std::cos(a), std::sin(a)});
        }
        return points;
    };
    LineMap map;
    map.insertSurface(scanAt(0), mrpt::poses::CPose2D(0, 0, 0));
    for (const LineMapPoint& p : map.points())
        EXPECT_EQ(p.views, 1u);
    map.insertSurface(scanAt(0.3), mrpt::poses::CPose2D(0.3, 0, 0));
    EXPECT_EQ(map.scans(), 2u);
    std::size_t wall = 0, confirmed = 0, disc = 0;
    for (const LineMapPoint& p : map.points()) {
        if (p.y > 0.9) {
            if (p.x > -0.65 && p.x < 1.45) {  // where both scans saw the wall
                ++wall;
                confirmed += p.views == 2;
            }
        } else {
            EXPECT_EQ(p.views, 1u) << p.x << ", " << p.y;
            ++disc;
        }
    }
    EXPECT_GE(disc, 10u);
    // A reading confirms only the point its lookup cell holds: points of the first scan that
    // the second's new points shadow in the lookup keep one view (here a third of them).
    ASSERT_GT(wall, 10u);
    EXPECT_GT(double(confirmed), 0.5 * double(wall)) << confirmed << " of " << wall;
    map.clear();
    EXPECT_EQ(map.scans(), 0u);
}

// firstScan: the scan that first showed a surface. A second scan's readings of the same wall
// fuse into the first scan's points, which keep it; what only the second scan saw is its own.
TEST(LineMap, RemembersTheScanThatFirstShowedEachSurface) {
    using matching::SurfacePoint;
    std::vector<SurfacePoint> wall, wallAndCorner;
    // Readings 0.2 m apart: each lookup finds the reading of the same spot, never a neighbour.
    for (double x = -1; x <= 1; x += 0.2)  // the wall y = 1
        wall.push_back({x, 1, 0, -1});
    wallAndCorner = wall;
    for (double y = -1; y <= 0.9; y += 0.2)  // and the wall x = 1.5, seen only from the second
        wallAndCorner.push_back({1.5, y, -1, 0});
    LineMap map;
    map.insertSurface(wall, mrpt::poses::CPose2D(0, 0, 0));
    map.insertSurface(wallAndCorner, mrpt::poses::CPose2D(0, 0, 0));
    std::size_t first = 0, second = 0;
    for (const LineMapPoint& p : map.points()) {
        if (p.y > 0.95 && p.x < 1.05) {
            EXPECT_EQ(p.firstScan, 1u) << p.x << ", " << p.y;
            ++first;
        } else if (p.x > 1.45) {
            EXPECT_EQ(p.firstScan, 2u) << p.x << ", " << p.y;
            ++second;
        }
    }
    EXPECT_EQ(first, wall.size()) << "the second scan's readings of the wall fused into it";
    EXPECT_EQ(second, wallAndCorner.size() - wall.size());
}

// clear() empties the map but keeps its memory; the refilled map answers as a new one does.
TEST(LineMap, AnswersAfterClearAsANewMapDoes) {
    LineMap reused, fresh;
    for (int i = 0; i < 50; ++i)
        reused.insert(pointAt(float(i), 0));
    reused.clear();
    EXPECT_EQ(reused.size(), 0u);
    EXPECT_EQ(reused.nearest(10, 0), nullptr);
    for (int i = 0; i < 20; ++i) {
        reused.insert(pointAt(0.3f * float(i), 5, 0, 1));
        fresh.insert(pointAt(0.3f * float(i), 5, 0, 1));
    }
    for (double x = -1; x < 7; x += 0.037) {
        const LineMapPoint* a = reused.nearest(x, 5.1);
        const LineMapPoint* b = fresh.nearest(x, 5.1);
        ASSERT_EQ(a == nullptr, b == nullptr) << x;
        if (a != nullptr) {
            EXPECT_EQ(a - reused.points().data(), b - fresh.points().data()) << x;
        }
    }
}

// reset() also forgets where the first point put the lattice: a map reused for a new submap
// (GraphSlam) answers every lookup exactly as a new map, where clear() keeps the old cells.
TEST(LineMap, AnswersAfterResetExactlyAsANewMapDoes) {
    LineMap reused, fresh;
    // Its first point anchors a lattice a fraction of a cell off the one the new points' first
    // point anchors in `fresh` (1.3 and 2.7 cm past a whole number of cells).
    for (int i = 0; i < 50; ++i)
        reused.insert(pointAt(30.013f + 0.2f * float(i), -20.027f, 0, 1));
    reused.reset();
    EXPECT_EQ(reused.size(), 0u);
    EXPECT_EQ(reused.scans(), 0u);
    EXPECT_EQ(reused.lookupCells(), 0u);
    EXPECT_EQ(reused.nearest(31, -20), nullptr);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> along(-3, 3), across(-0.02f, 0.02f);
    for (int i = 0; i < 200; ++i) {
        const float y = 5 + across(rng), x = along(rng);
        const LineMapPoint p = pointAt(x, y, 0, 1);
        reused.insert(p);
        fresh.insert(p);
    }
    ASSERT_EQ(reused.size(), fresh.size());
    EXPECT_EQ(reused.lookupCells(), fresh.lookupCells());
    int answered = 0;
    for (double x = -4; x < 4; x += 0.0037) {
        for (double y = 4.55; y < 5.45; y += 0.0113) {
            const LineMapPoint* a = reused.nearest(x, y);
            const LineMapPoint* b = fresh.nearest(x, y);
            ASSERT_EQ(a == nullptr, b == nullptr) << x << ", " << y;
            if (a != nullptr) {
                ++answered;
                ASSERT_EQ(a - reused.points().data(), b - fresh.points().data()) << x << ", " << y;
            }
        }
    }
    EXPECT_GT(answered, 10000);
}

// carve: a map point a scan's beams passed through by the margin or more counts a view
// through; a surface the beams end on does not, nor the corner of an object whose edge the
// beams graze (a neighbouring beam ends on it), nor a point nearer the scan's surface than the
// margin.
TEST(LineMap, CarveCountsTheScansThatSawThroughAPoint) {
    LineMap map;
    for (float x = -1.5f; x <= 1.5f; x += 0.05f)  // a wall y = 2, the scan sees it
        map.insert(pointAt(x, 2, 0, -1));
    map.insert(pointAt(0.5f, 1.0f, 0, -1));   // where a person stood: now free
    map.insert(pointAt(0.0f, 1.9f, 0, -1));   // 0.1 m in front of the wall: within the margin
    map.insert(pointAt(-0.4f, 1.0f, 0, -1));  // the corner of a box the scan sees
    map.insert(pointAt(-0.6f, 1.0f, 0, -1));  // its face
    // The scan from the origin, facing +y: the box's front face x in [-0.8, -0.4] at y = 1,
    // and the wall y = 2 behind it; a beam every 0.5 deg.
    const double step = M_PI / 360;
    std::vector<float> ranges;
    for (double a = M_PI / 4; a <= 3 * M_PI / 4 + 1e-9; a += step) {
        const double toWall = 2 / std::sin(a), x = std::cos(a) / std::sin(a);  // x at y = 1
        ranges.push_back(float(x >= -0.8 && x <= -0.4 ? 1 / std::sin(a) : toWall));
    }
    matching::PolarScan scan;
    scan.assign(M_PI / 4, step, ranges, std::vector<char>(ranges.size(), 1), 20.0);
    map.carve(scan, mrpt::poses::CPose2D(0, 0, 0), 0, 0.2);
    for (const LineMapPoint& p : map.points()) {
        const bool person = p.x == 0.5f && p.y == 1.0f;
        EXPECT_EQ(p.seenThrough, person ? 1u : 0u) << p.x << ", " << p.y;
        EXPECT_EQ(p.moved(), person) << p.x << ", " << p.y;
    }
    // Only the points from index `first` on are carved: the person's point again, once more.
    const std::size_t person = map.size() - 4;
    map.carve(scan, mrpt::poses::CPose2D(0, 0, 0), person + 1, 0.2);
    EXPECT_EQ(map.points()[person].seenThrough, 1u);
    map.carve(scan, mrpt::poses::CPose2D(0, 0, 0), person, 0.2);
    EXPECT_EQ(map.points()[person].seenThrough, 2u);
}

TEST(LineMap, CountSeenThroughJudgesAsCarveAndRecordsNothing) {
    LineMap map;
    for (float x = -1.5f; x <= 1.5f; x += 0.05f)  // a wall y = 2
        map.insert(pointAt(x, 2, 0, -1));
    map.insert(pointAt(0.5f, 1.0f, 0, -1));  // where a person stood: now free
    // The scan from the origin, facing +y, sees the wall; a beam every 0.5 deg.
    const double step = M_PI / 360;
    std::vector<float> ranges;
    for (double a = M_PI / 4; a <= 3 * M_PI / 4 + 1e-9; a += step)
        ranges.push_back(float(2 / std::sin(a)));
    matching::PolarScan scan;
    scan.assign(M_PI / 4, step, ranges, std::vector<char>(ranges.size(), 1), 20.0);
    EXPECT_EQ(map.countSeenThrough(scan, mrpt::poses::CPose2D(0, 0, 0), 0.2), 1u);
    // The same readings placed 0.1 m nearer the wall: within the margin, as seen.
    EXPECT_EQ(map.countSeenThrough(scan, mrpt::poses::CPose2D(0, 0.1, 0), 0.2), 1u);
    // 0.5 m nearer (a registration that slid along the heading): every beam reaches 0.5 m or
    // more beyond the wall, which the map's scans saw. From there the wall's ends lie at the
    // edges of the scan's 90 deg, where a beam lacks a neighbour: most of it, not all.
    const std::size_t slid = map.countSeenThrough(scan, mrpt::poses::CPose2D(0, 0.5, 0), 0.2);
    EXPECT_GE(slid, 2 * map.size() / 3);
    EXPECT_LE(slid, map.size());
    for (const LineMapPoint& p : map.points())
        EXPECT_EQ(p.seenThrough, 0u) << "counted, not recorded";
}

}  // namespace
}  // namespace toposlam
