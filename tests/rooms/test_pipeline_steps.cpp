// The steps of the virtual-door pipeline one by one, on tiny hand-made inputs.
#include <toposlam/rooms/ConnectedRuns.h>
#include <toposlam/rooms/DoorFilters.h>
#include <toposlam/rooms/DoorSearchPaths.h>
#include <toposlam/rooms/FreeSpaceBinarizer.h>
#include <toposlam/rooms/FurniturePockets.h>
#include <toposlam/rooms/LineMerger.h>
#include <toposlam/rooms/MainDirectionVoter.h>
#include <toposlam/rooms/ProbabilisticHough.h>
#include <toposlam/rooms/RegionBoundary.h>
#include <toposlam/rooms/RegionPartition.h>
#include <toposlam/rooms/RoomSegmentationJob.h>
#include <toposlam/rooms/RoomSegmenter.h>
#include <toposlam/rooms/VirtualDoorDetector.h>
#include <toposlam/rooms/WallThickness.h>

#include "DrawnMaps.h"
#include "GridRay.h"
#include "LabelRuns.h"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

using namespace toposlam::rooms;

namespace {

constexpr double kRes = 0.05;

FreeSpace spaceOf(const cv::Mat& free) {
    return FreeSpaceBinarizer().binarize(free, toposlam::rooms::test::frameOf(free));
}

// A 6 x 4 m room split by a wall at x = 3 m with a gap of `gap` m centred at y = 2 m.
cv::Mat twoRooms(double gap) {
    cv::Mat img(80, 120, CV_8U, cv::Scalar(0));
    img(cv::Rect(2, 2, 116, 76)) = 255;
    img(cv::Rect(58, 0, 4, 80)) = 0;
    const int half = static_cast<int>(std::lround(gap / kRes / 2));
    img(cv::Rect(58, 40 - half, 4, 2 * half)) = 255;
    return img;
}

}  // namespace

TEST(LineMerger, MergesOverlappingPiecesOfOneWall) {
    const LineSegment a{{0, 0}, {10, 0}}, b{{8, 0.5f}, {20, 0.5f}};
    EXPECT_TRUE(LineMerger::canMerge(a, b, 5 * M_PI / 180, 2.0));
    const auto merged = LineMerger().merge({a, b}, kRes);
    ASSERT_EQ(merged.size(), 1u);
    // The base (the longer, b) is extended over a's projection: from x = 0 to 20.
    EXPECT_NEAR(std::min(merged[0].start.x, merged[0].end.x), 0.0, 1e-4);
    EXPECT_NEAR(std::max(merged[0].start.x, merged[0].end.x), 20.0, 1e-4);
}

TEST(LineMerger, KeepsParallelWallsPerpendicularWallsAndDistantPieces) {
    const LineSegment base{{0, 0}, {10, 0}};
    EXPECT_FALSE(LineMerger::canMerge(base, {{0, 20}, {10, 20}}, 5 * M_PI / 180, 2.0));  // eq. 6
    EXPECT_FALSE(LineMerger::canMerge(base, {{5, -5}, {5, 5}}, 5 * M_PI / 180, 2.0));    // eq. 5
    EXPECT_FALSE(LineMerger::canMerge(base, {{30, 0}, {40, 0}}, 5 * M_PI / 180, 2.0));   // eq. 7
    // Reversed endpoints are the same direction (undirected segments).
    EXPECT_TRUE(LineMerger::canMerge(base, {{12, 0.5f}, {5, 0.5f}}, 5 * M_PI / 180, 2.0));
}

namespace {

// Eqs. 5-7 and the merge loop as the paper states them, every quantity computed afresh for
// every pair: the reference LineMerger::merge must agree with exactly.
bool referenceCanMerge(const LineSegment& a, const LineSegment& b, double maxAngle,
                       double maxDistance) {
    const cv::Point3d la = a.homogeneous(), lb = b.homogeneous();
    const double na = std::hypot(la.x, la.y), nb = std::hypot(lb.x, lb.y);
    const double angle =
        na == 0 || nb == 0
            ? 0
            : std::acos(std::min(1.0, std::abs(la.x * lb.x + la.y * lb.y) / (na * nb)));
    if (angle >= maxAngle)
        return false;
    if (0.5 * (a.lineDistance(b.start) + a.lineDistance(b.end)) >= maxDistance)
        return false;
    const cv::Point2f dm = a.midpoint() - b.midpoint();
    return std::hypot(dm.x, dm.y) < 0.5 * (a.length() + b.length());
}

std::vector<LineSegment> referenceMerge(std::vector<LineSegment> lines, double maxAngle,
                                        double maxDistance) {
    for (bool merged = true; merged;) {
        merged = false;
        std::sort(lines.begin(), lines.end(), [](const LineSegment& a, const LineSegment& b) {
            return a.length() > b.length();
        });
        std::vector<bool> gone(lines.size(), false);
        for (std::size_t i = 0; i < lines.size(); ++i) {
            for (std::size_t j = i + 1; !gone[i] && j < lines.size(); ++j) {
                if (gone[j] || !referenceCanMerge(lines[i], lines[j], maxAngle, maxDistance))
                    continue;
                // Extend i along its line over j's projected endpoints.
                LineSegment& base = lines[i];
                const cv::Point2f d = base.end - base.start;
                const double len = std::hypot(d.x, d.y);
                if (len > 0) {
                    const cv::Point2f u(static_cast<float>(d.x / len),
                                        static_cast<float>(d.y / len));
                    auto along = [&](const cv::Point2f& p) {
                        return static_cast<double>((p - base.start).dot(u));
                    };
                    const double t0 = std::min({0.0, along(lines[j].start), along(lines[j].end)});
                    const double t1 = std::max({len, along(lines[j].start), along(lines[j].end)});
                    const cv::Point2f s = base.start;
                    base.start = s + u * static_cast<float>(t0);
                    base.end = s + u * static_cast<float>(t1);
                }
                gone[j] = true;
                merged = true;
            }
        }
        std::vector<LineSegment> kept;
        for (std::size_t i = 0; i < lines.size(); ++i)
            if (!gone[i])
                kept.push_back(lines[i]);
        lines = kept;
    }
    return lines;
}

}  // namespace

// Hough-like input: pieces of a few walls, a cell or so off their line and a few degrees off
// their direction, some exactly at the angle threshold. LineMerger computes each segment's
// geometry once and decides the angle by its cosine away from the threshold; the merges must
// be those of the equations evaluated pair by pair.
TEST(LineMerger, MergesExactlyAsTheEquationsEvaluatedPairByPair) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0, 1);
    const double maxAngle = 5 * M_PI / 180, maxDistance = 0.1 / kRes;
    std::size_t pieces = 0, mergedAway = 0;
    for (int map = 0; map < 40; ++map) {
        std::vector<LineSegment> lines;
        for (int wall = 0; wall < 12; ++wall) {
            const double a = unit(rng) * M_PI, ox = 300 * unit(rng), oy = 300 * unit(rng);
            for (int piece = 0; piece < 6; ++piece) {
                // Pieces on the wall's direction and exactly 5 degrees off it (pairs at the
                // threshold, give or take the rounding of float endpoints), the others within
                // 6 degrees.
                const double off = piece % 3 == 0   ? maxAngle
                                   : piece % 3 == 1 ? 0.0
                                                    : (unit(rng) - 0.5) * 12 * M_PI / 180;
                const double t = 60 * unit(rng), len = 5 + 30 * unit(rng), side = 3 * unit(rng);
                const double px = ox + t * std::cos(a) - side * std::sin(a);
                const double py = oy + t * std::sin(a) + side * std::cos(a);
                lines.push_back({cv::Point2f(static_cast<float>(px), static_cast<float>(py)),
                                 cv::Point2f(static_cast<float>(px + len * std::cos(a + off)),
                                             static_cast<float>(py + len * std::sin(a + off)))});
            }
        }
        const auto expected = referenceMerge(lines, maxAngle, maxDistance);
        const auto merged = LineMerger().merge(lines, kRes);
        ASSERT_EQ(merged.size(), expected.size()) << "map " << map;
        for (std::size_t k = 0; k < merged.size(); ++k) {
            EXPECT_EQ(merged[k].start, expected[k].start) << "map " << map << " line " << k;
            EXPECT_EQ(merged[k].end, expected[k].end) << "map " << map << " line " << k;
        }
        pieces += lines.size();
        mergedAway += lines.size() - merged.size();
    }
    EXPECT_GT(mergedAway, pieces / 4);  // the input does merge, a lot
}

TEST(MainDirectionVoter, PicksTheLongestDirectionAndItsPerpendicular) {
    auto at = [](double deg, double length) {
        const double a = deg * M_PI / 180;
        return LineSegment{
            {0, 0},
            {static_cast<float>(length * std::cos(a)), static_cast<float>(length * std::sin(a))}};
    };
    const auto d = MainDirectionVoter().vote({at(20, 100), at(21, 80), at(112, 50), at(65, 60)});
    EXPECT_NEAR(d.phi1 * 180 / M_PI, 20.4, 0.5);   // length-weighted mean of the 20/21 deg bin
    EXPECT_NEAR(d.phi2 * 180 / M_PI, 112.0, 0.5);  // closest to perpendicular, not the 65 deg one
    // 1 deg and 179 deg are one direction: together they outvote 90 deg.
    const auto e = MainDirectionVoter().vote({at(1, 60), at(179, 60), at(90, 100)});
    EXPECT_LT(std::min(e.phi1, M_PI - e.phi1), 2 * M_PI / 180);
}

TEST(VirtualDoorDetector, RayStopsAtADiagonalWall) {
    cv::Mat free(40, 40, CV_8U, cv::Scalar(255));
    for (int k = 0; k < 40; ++k)
        free.at<std::uint8_t>(k, 39 - k) = 0;  // 8-connected anti-diagonal
    cv::Point hit;
    ASSERT_TRUE(
        VirtualDoorDetector::castRay(free, {5, 5}, std::sqrt(0.5), std::sqrt(0.5), 100, hit));
    EXPECT_LE(std::abs(hit.x + hit.y - 39), 1);  // on the wall, not beyond it
}

// detect() walks each main direction's ray once and looks it up from every cell, and walks the
// ray behind a cell only as far as a door could still reach: it must find exactly the doors
// that casting both rays in full from every cell finds (eq. 10), near the image border too,
// each cut once (the first cell to find it gives it).
TEST(VirtualDoorDetector, SameDoorsAsFullRaysFromEveryCell) {
    cv::Mat noise(70, 90, CV_8U);
    cv::RNG rng(7);
    rng.fill(noise, cv::RNG::UNIFORM, 0, 100);
    FreeSpace space;
    space.frame.resolution = kRes;
    space.free = noise >= 6;        // 6 % single obstacle cells
    for (int k = 0; k < 12; ++k) {  // and walls of any length and angle
        const int ay = rng.uniform(0, 70), ax = rng.uniform(0, 90);  // one draw per statement
        const int by = rng.uniform(0, 70), bx = rng.uniform(0, 90);
        const cv::Point a(ax, ay), b(bx, by);
        cv::line(space.free, a, b, cv::Scalar(0), 1, cv::LINE_8);
    }
    space.frame.cols = space.free.cols;
    space.frame.rows = space.free.rows;
    std::vector<cv::Point> cells;
    std::vector<double> local;
    cv::findNonZero(space.free, cells);
    for (std::size_t i = 0; i < cells.size(); ++i)
        local.push_back(0.013 * static_cast<double>(i));
    const std::vector<double> axes{0.3, 0.3 + M_PI / 2};
    for (const double width : {1.1, 2.3}) {  // doors; the wide openings' range
        VirtualDoorDetector::Options o;
        o.doorWidth = width;
        o.doorWidthTolerance = 0.5;
        const auto found = VirtualDoorDetector(o).detect(space, cells, axes, local);
        const double target = width / kRes, tolerance = 0.5 / kRes, reach = target + tolerance + 1;
        std::vector<VirtualDoor> expected;
        // Each cut once, as the first cell found it (whichever jamb it met first).
        std::set<std::pair<std::pair<int, int>, std::pair<int, int>>> cuts;
        const auto firstTime = [&](const cv::Point& a, const cv::Point& b) {
            const std::pair<int, int> p{a.y, a.x}, q{b.y, b.x};
            return cuts.insert(p < q ? std::pair{p, q} : std::pair{q, p}).second;
        };
        for (std::size_t i = 0; i < cells.size(); ++i) {
            for (int k = 0; k < 3; ++k) {
                const double direction = k < 2 ? axes[static_cast<std::size_t>(k)] : local[i];
                const double ux = std::cos(direction), uy = std::sin(direction);
                cv::Point a, b;
                if (!VirtualDoorDetector::castRay(space.free, cells[i], ux, uy, reach, a) ||
                    !VirtualDoorDetector::castRay(space.free, cells[i], -ux, -uy, reach, b))
                    continue;
                const double w = std::hypot(a.x - b.x, a.y - b.y);
                if (std::abs(w - target) < tolerance && firstTime(a, b))
                    expected.push_back({a, b, w, k, cells[i]});
            }
        }
        ASSERT_EQ(found.size(), expected.size()) << width;
        ASSERT_GT(found.size(), 100u) << "the test must find doors";
        for (std::size_t i = 0; i < found.size(); ++i) {
            EXPECT_EQ(found[i].jambA, expected[i].jambA) << i;
            EXPECT_EQ(found[i].jambB, expected[i].jambB) << i;
            EXPECT_EQ(found[i].width, expected[i].width) << i;
            EXPECT_EQ(found[i].direction, expected[i].direction) << i;
            EXPECT_EQ(found[i].pathCell, expected[i].pathCell) << i;
        }
    }
}

TEST(VirtualDoorDetector, DoorsAFullWordOfCellsApartAreTwoCuts) {
    // The same door twice, 65536 cells apart (3.3 km at 5 cm, 655 m at 1 cm): two cuts, not one
    // cut found twice, however the jamb cells would be packed into a key.
    const cv::Mat door = twoRooms(0.9);
    constexpr int kApart = 1 << 16;
    FreeSpace space;
    space.frame.resolution = kRes;
    space.free = cv::Mat(door.rows, kApart + door.cols, CV_8U, cv::Scalar(255));
    door.copyTo(space.free(cv::Rect(0, 0, door.cols, door.rows)));
    door.copyTo(space.free(cv::Rect(kApart, 0, door.cols, door.rows)));
    space.frame.cols = space.free.cols;
    space.frame.rows = space.free.rows;
    const auto doors =
        VirtualDoorDetector().detect(space, {{60, 40}, {kApart + 60, 40}}, {0.0, M_PI / 2});
    ASSERT_EQ(doors.size(), 2u);
    EXPECT_EQ(doors[1].jambA.x - doors[0].jambA.x, kApart);
    EXPECT_EQ(doors[1].jambA.y, doors[0].jambA.y);
}

TEST(VirtualDoorDetector, FindsDoorWideGapsOnly) {
    const std::vector<double> axes{0.0, M_PI / 2};
    for (const double gap : {0.7, 0.9, 1.2, 1.5}) {
        const FreeSpace space = spaceOf(twoRooms(gap));
        const auto doors = VirtualDoorDetector().detect(space, {{60, 40}}, axes);
        ASSERT_EQ(doors.size(), 1u) << gap;
        EXPECT_EQ(doors[0].direction, 1);  // found across (along y), not along x
        EXPECT_NEAR(doors[0].width * kRes, gap + kRes, kRes);  // jamb cell centres: one cell more
    }
    for (const double gap : {0.4, 2.0}) {  // outside 1.1 +- 0.5 m
        const FreeSpace space = spaceOf(twoRooms(gap));
        EXPECT_TRUE(VirtualDoorDetector().detect(space, {{60, 40}}, axes).empty()) << gap;
    }
}

TEST(Clearance, RidgeDirectionIsTheDoorLine) {
    const FreeSpace space = spaceOf(twoRooms(0.9));
    const Clearance clearance(space.free);
    // The door line of a gap in a vertical wall is vertical (pi/2 in the image).
    EXPECT_NEAR(clearance.acrossRidge({60, 40}), M_PI / 2, 0.15);
    cv::Mat t;
    cv::transpose(twoRooms(0.9), t);
    const Clearance transposed(spaceOf(t).free);
    const double a = transposed.acrossRidge({40, 60});
    EXPECT_LT(std::min(a, M_PI - a), 0.15);
}

TEST(Clearance, IsOpenCvsFiveByFiveDistanceTransformToTheBit) {
    cv::RNG rng(59);
    Clearance clearance;  // one object: compute() reuses its buffers across sizes
    auto expectSame = [&](const cv::Mat& free, const std::string& what) {
        cv::Mat expected;
        cv::distanceTransform(free, expected, cv::DIST_L2, cv::DIST_MASK_5);
        clearance.compute(free);
        ASSERT_EQ(clearance.distances().size(), free.size()) << what;
        EXPECT_EQ(cv::norm(expected, clearance.distances(), cv::NORM_INF), 0) << what;
    };
    // Widths around the blocks of four (and whole blocks), one-pixel strips, and an image with no
    // obstacle (every distance "far"); obstacles from sparse to dense.
    for (const cv::Size size :
         {cv::Size(1, 1), cv::Size(7, 1), cv::Size(1, 7), cv::Size(4, 3), cv::Size(8, 2),
          cv::Size(5, 5), cv::Size(13, 9), cv::Size(64, 37), cv::Size(203, 150)}) {
        for (const double obstacles : {0.0, 0.002, 0.05, 0.5}) {
            cv::Mat free(size, CV_8U);
            for (int r = 0; r < free.rows; ++r) {
                for (int c = 0; c < free.cols; ++c)
                    free.at<std::uint8_t>(r, c) = rng.uniform(0.0, 1.0) < obstacles ? 0 : 255;
            }
            expectSame(free, std::to_string(size.width) + "x" + std::to_string(size.height) +
                                 " obstacles " + std::to_string(obstacles));
        }
    }
    // A drawn map, whole and as a view into it (the segmenter passes its cropped free space).
    const FreeSpace space = spaceOf(twoRooms(0.9));
    expectSame(space.free, "two rooms");
    expectSame(space.free(cv::Rect(3, 5, space.free.cols - 10, space.free.rows - 7)), "a view");
}

namespace {

// Random cells, set with probability `share` (0 or 255).
cv::Mat randomCells(cv::RNG& rng, cv::Size size, double share) {
    cv::Mat cells(size, CV_8U);
    for (int r = 0; r < cells.rows; ++r) {
        for (int c = 0; c < cells.cols; ++c)
            cells.at<std::uint8_t>(r, c) = rng.uniform(0.0, 1.0) < share ? 255 : 0;
    }
    return cells;
}

}  // namespace

TEST(ConnectedRuns, IsOpenCvsFourConnectedLabellingToTheLabel) {
    cv::RNG rng(60);
    ConnectedRuns runs;  // one object: find() reuses its buffers across sizes
    for (const cv::Size size : {cv::Size(1, 1), cv::Size(9, 1), cv::Size(1, 9), cv::Size(8, 8),
                                cv::Size(17, 13), cv::Size(64, 37), cv::Size(203, 150)}) {
        for (const double share : {0.0, 0.1, 0.5, 0.9, 1.0}) {
            const cv::Mat cells = randomCells(rng, size, share);
            const std::string what = std::to_string(size.width) + "x" +
                                     std::to_string(size.height) + " share " +
                                     std::to_string(share);
            for (const auto which : {ConnectedRuns::Cells::NonZero, ConnectedRuns::Cells::Zero}) {
                cv::Mat expected, labels;
                const int n = cv::connectedComponents(
                    which == ConnectedRuns::Cells::NonZero ? cells : cells == 0, expected, 4,
                    CV_32S);
                ASSERT_EQ(runs.find(cells, 4, which), n) << what;
                runs.paint(labels);
                EXPECT_EQ(cv::countNonZero(labels != expected), 0) << what;
                std::vector<int> areas(static_cast<std::size_t>(n), 0);
                for (auto it = expected.begin<int>(); it != expected.end<int>(); ++it) {
                    if (*it != 0)
                        ++areas[static_cast<std::size_t>(*it)];
                }
                EXPECT_EQ(runs.areas(), areas) << what;
            }
        }
    }
}

TEST(ConnectedRuns, EightConnectedAreOpenCvsComponentsInRasterOrder) {
    cv::RNG rng(8);
    ConnectedRuns runs;
    for (int trial = 0; trial < 40; ++trial) {
        const cv::Mat cells =
            randomCells(rng, {rng.uniform(1, 90), rng.uniform(1, 90)}, rng.uniform(0.05, 0.95));
        cv::Mat expected, labels;
        const int n = cv::connectedComponents(cells, expected, 8, CV_32S);
        ASSERT_EQ(runs.find(cells, 8), n);
        runs.paint(labels);
        // The same components: a one-to-one map between the two numberings; and ours numbered
        // in the raster order of their first cells.
        std::vector<int> ours(static_cast<std::size_t>(n), -1), theirs(ours);
        int next = 1;
        for (int r = 0; r < cells.rows; ++r) {
            for (int c = 0; c < cells.cols; ++c) {
                const int a = labels.at<int>(r, c), b = expected.at<int>(r, c);
                ASSERT_EQ(a == 0, b == 0);
                if (a == 0)
                    continue;
                if (ours[static_cast<std::size_t>(b)] < 0) {
                    ASSERT_EQ(a, next++);
                    ours[static_cast<std::size_t>(b)] = a;
                }
                if (theirs[static_cast<std::size_t>(a)] < 0)
                    theirs[static_cast<std::size_t>(a)] = b;
                ASSERT_EQ(ours[static_cast<std::size_t>(b)], a);
                ASSERT_EQ(theirs[static_cast<std::size_t>(a)], b);
            }
        }
        EXPECT_EQ(next, n);
    }
}

TEST(ConnectedRuns, DiagonalCellsJoinOnlyEightConnected) {
    cv::Mat cells = cv::Mat::zeros(4, 4, CV_8U);
    cells.at<std::uint8_t>(0, 0) = cells.at<std::uint8_t>(1, 1) = 255;
    cells.at<std::uint8_t>(2, 3) = cells.at<std::uint8_t>(3, 2) = 255;
    ConnectedRuns runs;
    EXPECT_EQ(runs.find(cells, 4), 5);
    EXPECT_EQ(runs.find(cells, 8), 3);
    EXPECT_EQ(runs.areas(), (std::vector<int>{0, 2, 2}));
    // The zero cells: the corner cell the second pair closes off, and the rest round both.
    EXPECT_EQ(runs.find(cells, 4, ConnectedRuns::Cells::Zero), 3);
    EXPECT_EQ(runs.areas(), (std::vector<int>{0, 11, 1}));
    EXPECT_EQ(runs.find(cells, 8, ConnectedRuns::Cells::Zero), 2);
}

TEST(LabelRuns, RunEndIsWhereTheLabelChanges) {
    // Rows of every length around the blocks of four, runs from one cell to many.
    cv::RNG rng(61);
    for (int cols = 1; cols <= 19; ++cols) {
        for (int trial = 0; trial < 50; ++trial) {
            std::vector<int> row(static_cast<std::size_t>(cols));
            int label = 0;
            for (int& cell : row) {
                if (rng.uniform(0, 5) == 0)
                    label = rng.uniform(-1, 3);
                cell = label;
            }
            for (int x = 0; x < cols; ++x) {
                int end = x;
                while (end < cols &&
                       row[static_cast<std::size_t>(end)] == row[static_cast<std::size_t>(x)])
                    ++end;
                ASSERT_EQ(detail::runEnd(row.data(), x, cols), end) << cols << " cells from " << x;
            }
        }
    }
}

TEST(RayPattern, IsTheWalkOfItsRayFromEveryCell) {
    // A pattern is walked once per direction and then looked up from any cell: it must give
    // the cell walkRay() gives, also where the ray leaves the mask (outside counts as not set)
    // and from outside it, at full length and cut short.
    cv::RNG rng(61);
    cv::Mat mask(23, 37, CV_8U);
    for (int r = 0; r < mask.rows; ++r) {
        for (int c = 0; c < mask.cols; ++c)
            mask.at<std::uint8_t>(r, c) = rng.uniform(0.0, 1.0) < 0.08 ? 0 : 255;
    }
    for (const double degrees : {0.0, 0.5, 17.0, 45.0, 90.0, 135.0, 180.0, 200.0, 270.0, 301.0}) {
        const double ux = std::cos(degrees * M_PI / 180), uy = std::sin(degrees * M_PI / 180);
        for (const double reach : {21.0, 6.0}) {
            const detail::RayPattern pattern(ux, uy, reach, mask);
            for (int y = -1; y <= mask.rows; ++y) {
                for (int x = -1; x <= mask.cols; ++x) {
                    const cv::Point from(x, y);
                    for (const double length : {reach, 0.5 * reach}) {
                        cv::Point expected(-100, -100), hit(-100, -100);
                        const bool walked = detail::walkRay(
                            from, ux, uy, length,
                            [&](int cx, int cy) { return !detail::isSet(mask, cx, cy); }, expected);
                        const bool found = length == reach
                                               ? pattern.firstUnset(mask, from, hit)
                                               : pattern.firstUnset(mask, from, length, hit);
                        ASSERT_EQ(found, walked) << degrees << " deg from " << from;
                        if (walked) {
                            ASSERT_EQ(hit, expected) << degrees << " deg from " << from;
                        }
                    }
                }
            }
        }
    }
}

TEST(ProbabilisticHough, IsOpenCvsHoughLinesPToTheSegment) {
    cv::RNG rng(61);
    ProbabilisticHough hough;  // one object: find() reuses its buffers across sizes and steps
    auto expectSame = [&](const cv::Mat& image, const ProbabilisticHough::Parameters& p,
                          const std::string& what) {
        std::vector<cv::Vec4i> expected, ours;
        cv::HoughLinesP(image, expected, p.rho, p.theta, p.threshold, p.minLineLength,
                        p.maxLineGap);
        hough.find(image, p, ours);
        EXPECT_EQ(ours, expected) << what;
    };
    // Walls at any angle, 4- and 8-connected, with gaps and specks, on images whose widths
    // fall on and off the blocks of four angles; the steps and thresholds the extractor uses
    // and others.
    std::vector<std::pair<cv::Mat, std::string>> images;
    for (const cv::Size size : {cv::Size(1, 9), cv::Size(9, 1), cv::Size(37, 23), cv::Size(120, 80),
                                cv::Size(203, 150)}) {
        for (const int walls : {0, 3, 12}) {
            cv::Mat image = cv::Mat::zeros(size, CV_8U);
            for (int k = 0; k < walls; ++k) {
                const cv::Point a(rng.uniform(0, size.width), rng.uniform(0, size.height));
                const cv::Point b(rng.uniform(0, size.width), rng.uniform(0, size.height));
                cv::line(image, a, b, cv::Scalar(255), 1, k % 2 == 0 ? cv::LINE_8 : cv::LINE_4);
            }
            for (int k = 0; k < size.area() / 50; ++k)
                image.at<std::uint8_t>(rng.uniform(0, size.height), rng.uniform(0, size.width)) ^=
                    255;
            images.emplace_back(image, std::to_string(size.width) + "x" +
                                           std::to_string(size.height) + " walls " +
                                           std::to_string(walls));
        }
    }
    // The wall faces of a drawn map, whole and as a view into it (the extractor's crop).
    const FreeSpace space = spaceOf(twoRooms(0.9));
    cv::Mat grown, faces;
    cv::dilate(space.free, grown, cv::Mat());
    cv::bitwise_xor(grown, space.free, faces);
    images.emplace_back(faces, "two rooms");
    images.emplace_back(faces(cv::Rect(3, 5, faces.cols - 10, faces.rows - 7)), "a view");
    for (const auto& [image, name] : images) {
        for (const double degrees : {1.0, 0.5, 2.0, 3.0}) {
            for (const int threshold : {2, 8, 20}) {
                ProbabilisticHough::Parameters p;
                p.theta = degrees * CV_PI / 180;
                p.threshold = threshold;
                p.minLineLength = threshold == 8 ? 10 : 0;
                p.maxLineGap = threshold == 2 ? 0 : 2;
                expectSame(image, p,
                           name + " at " + std::to_string(degrees) + " deg, threshold " +
                               std::to_string(threshold));
            }
        }
        ProbabilisticHough::Parameters coarse;  // two-pixel distance steps
        coarse.rho = 2;
        coarse.theta = CV_PI / 180;
        coarse.threshold = 5;
        coarse.minLineLength = 4;
        coarse.maxLineGap = 3;
        expectSame(image, coarse, name + " at rho 2");
    }
}

TEST(ConnectedRuns, LabelsAViewAndPaintsIntoOne) {
    // The segmenter labels a box inside a larger image and paints into a box of another.
    const FreeSpace space = spaceOf(twoRooms(0.9));
    const cv::Rect box(3, 5, space.free.cols - 10, space.free.rows - 7);
    ConnectedRuns runs;
    cv::Mat expected;
    const int n = cv::connectedComponents(space.free(box).clone(), expected, 4, CV_32S);
    ASSERT_EQ(runs.find(space.free(box), 4), n);
    cv::Mat whole(space.free.size(), CV_32S, cv::Scalar(-1));
    cv::Mat view = whole(box);
    runs.paint(view);
    EXPECT_EQ(view.data, whole.ptr(box.y) + box.x * sizeof(int));  // painted in place
    EXPECT_EQ(cv::countNonZero(view != expected), 0);
    EXPECT_EQ(cv::countNonZero(whole == -1), static_cast<int>(whole.total() - box.area()));
}

TEST(DoorSearchPaths, MedialAxisCrossesTheDoor) {
    const FreeSpace space = spaceOf(twoRooms(0.9));
    const auto cells = DoorSearchPaths::fromMedialAxis(space, Clearance(space.free), 0.6, 1.6);
    bool throughDoor = false;
    for (const auto& c : cells)
        throughDoor = throughDoor || (c.x >= 58 && c.x <= 61 && std::abs(c.y - 40) <= 1);
    EXPECT_TRUE(throughDoor);
}

TEST(DoorSearchPaths, TrajectoryCellsJoinConsecutivePoses) {
    const FreeSpace space = spaceOf(twoRooms(0.9));
    // Two poses 4 m apart through the door: every cell between them is on the path.
    const auto cells = DoorSearchPaths::fromTrajectory(space, {{1.0, 2.0, 0}, {5.0, 2.0, 0}});
    EXPECT_GE(cells.size(), 79u);
    for (const auto& c : cells)
        EXPECT_NE(space.free.at<std::uint8_t>(c), 0);
}

namespace {

// A 5 x 3 m room with nothing in it: where the distance filter looks for walls, none.
cv::Mat openRoomImage() {
    cv::Mat img(60, 100, CV_8U, cv::Scalar(0));
    img(cv::Rect(1, 1, 98, 58)) = 255;
    return img;
}

FreeSpace openRoom() {
    return spaceOf(openRoomImage());
}

}  // namespace

TEST(DoorFilters, DistanceFilterKeepsTheNarrowestOfAGroup) {
    const FreeSpace open = openRoom();
    std::vector<VirtualDoor> doors;
    for (int k = 0; k < 5; ++k) {  // parallel cuts 1 cell apart, the middle one narrowest
        const double w = 20 - (k == 2 ? 2 : 0);
        doors.push_back({{10 + k, 10}, {10 + k, static_cast<int>(10 + w)}, w, 0, {10 + k, 15}});
    }
    doors.push_back({{50, 10}, {50, 30}, 20, 0, {50, 20}});  // far away: its own group
    const auto kept = DoorFilters().distance(open, doors);
    ASSERT_EQ(kept.size(), 2u);
    EXPECT_EQ(kept[0].jambA.x, 12);
    DoorFilters::Options paper;
    paper.keepNarrowestOfGroup = false;
    const auto greedy = DoorFilters(paper).distance(open, doors);
    ASSERT_EQ(greedy.size(), 2u);
    EXPECT_EQ(greedy[0].jambA.x, 10);  // the paper: first come, first kept
}

TEST(DoorFilters, DistanceFilterChainsGroups) {
    // Cuts 8 cells apart (N_d = 10 cells): the first and the last are 32 cells apart, but the
    // chain joins them into one group, of which the narrowest is kept.
    const FreeSpace open = openRoom();
    std::vector<VirtualDoor> doors;
    for (int k = 0; k < 5; ++k) {
        const double w = 20 - (k == 3 ? 1 : 0);
        doors.push_back({{10 + 8 * k, 10}, {10 + 8 * k, static_cast<int>(10 + w)}, w, 0, {0, 0}});
    }
    const auto kept = DoorFilters().distance(open, doors);
    ASSERT_EQ(kept.size(), 1u);
    EXPECT_EQ(kept[0].jambA.x, 34);
}

TEST(DoorFilters, CutsFanningFromOneJambAreOneOpeningWhereTheirFarSideIsWall) {
    // From the jamb cell (40, 30) one cut runs 16 cells to the right, one 22 cells at 45
    // degrees down-right: the far side of their triangle, from (56, 30) to (55, 45), is open
    // floor in an empty room (a third opening: both cuts stay), and wall once a wall stands
    // just beyond it (one opening: the narrower cut stays).
    const std::vector<VirtualDoor> doors = {{{40, 30}, {56, 30}, 16, 0, {48, 30}},
                                            {{40, 30}, {55, 45}, std::hypot(15, 15), 0, {47, 37}}};
    EXPECT_EQ(DoorFilters().distance(openRoom(), doors).size(), 2u);

    cv::Mat img = openRoomImage();
    img(cv::Rect(58, 25, 4, 30)) = 0;  // a wall 2-3 cells beyond the far side
    const auto kept = DoorFilters().distance(spaceOf(img), doors);
    ASSERT_EQ(kept.size(), 1u);
    EXPECT_EQ(kept[0].jambB, cv::Point(56, 30));

    // Beyond 60 degrees apart: two doors whatever lies beyond.
    const std::vector<VirtualDoor> apart = {{{40, 30}, {56, 30}, 16, 0, {48, 30}},
                                            {{40, 30}, {46, 45}, std::hypot(6, 15), 0, {43, 37}}};
    EXPECT_EQ(DoorFilters().distance(spaceOf(img), apart).size(), 2u);
}

TEST(DoorFilters, MinimumAreaMergesSmallestFirstThroughTheWidestCut) {
    // A 12 x 2 m strip cut at x = 4, 5 and 9 m into regions of 8, 2, 8 and 6 m^2 (40 px wide
    // cuts): with N_s = 3 m^2 only the 2 m^2 sliver is too small; it joins a neighbour
    // through its wider cut (the narrower one is the waist), and both other cuts stay doors.
    cv::Mat free(40, 240, CV_8U, cv::Scalar(255));
    auto cut = [](int x, int top, int bottom) {
        const double w = bottom - top;
        return VirtualDoor{{x, top}, {x, bottom}, w, 0, {x, 20}};
    };
    // The sliver's left cut is 22 cells (1.1 m, a door's width), its right cut 39 cells.
    free(cv::Rect(80, 0, 1, 9)).setTo(0);
    free(cv::Rect(80, 31, 1, 9)).setTo(0);
    const std::vector<VirtualDoor> doors = {cut(80, 9, 31), cut(100, 0, 39), cut(180, 0, 39)};
    const RegionPartition partition(free, doors);
    ASSERT_EQ(partition.regionCount(), 4);
    DoorFilters::Options o;
    o.minRoomArea = 3.0;
    const auto rooms = DoorFilters(o).minimumArea(partition, doors,
                                                  DoorFilters::adjacency(partition), kRes * kRes);
    EXPECT_EQ(rooms.roomCount, 3);
    ASSERT_EQ(rooms.doors.size(), 2u);
    EXPECT_EQ(rooms.doors[0].door, 0u);  // the narrower cut survives
    EXPECT_EQ(rooms.doors[1].door, 2u);
    // The paper's single pass removes every cut next to the sliver instead.
    o.mergeSmallestFirst = false;
    const auto paper = DoorFilters(o).minimumArea(partition, doors,
                                                  DoorFilters::adjacency(partition), kRes * kRes);
    EXPECT_EQ(paper.roomCount, 2);
    ASSERT_EQ(paper.doors.size(), 1u);
    EXPECT_EQ(paper.doors[0].door, 2u);
}

TEST(RegionPartition, RunsAndCutCellsAreTheLabelImage) {
    // Random free space cut by random lines, some crossing, some diagonal, some off the image's
    // edge: the region runs paint the label image, and the cut cells are its free zeros.
    cv::RNG rng(6);
    RegionPartition partition;  // one object: compute() reuses its buffers
    for (int trial = 0; trial < 20; ++trial) {
        const cv::Mat free = randomCells(rng, {rng.uniform(20, 90), rng.uniform(20, 90)}, 0.9);
        std::vector<VirtualDoor> doors;
        for (int k = rng.uniform(0, 6); k > 0; --k) {
            const cv::Point a(rng.uniform(0, free.cols), rng.uniform(0, free.rows));
            const cv::Point b(rng.uniform(0, free.cols), rng.uniform(0, free.rows));
            doors.push_back({a, b, cv::norm(a - b), 0, a});
        }
        partition.compute(free, doors);
        cv::Mat painted = cv::Mat::zeros(free.size(), CV_32S);
        for (const auto& run : partition.regionRuns())
            painted(cv::Rect(run.begin, run.row, run.end - run.begin, 1)).setTo(run.label);
        EXPECT_EQ(cv::countNonZero(painted != partition.labels()), 0) << "trial " << trial;
        std::vector<cv::Point> cuts;
        cv::findNonZero((free != 0) & (partition.labels() == 0), cuts);  // raster order
        EXPECT_EQ(partition.cutCells(), cuts) << "trial " << trial;
    }
}

TEST(DoorFilters, ConstrictionRejectsCorridorCrossSections) {
    // A 1 m corridor, 6 m long, between two rooms: its cross-sections are door-wide but the
    // corridor does not widen within a door width of them; the doorway at its end does.
    cv::Mat img(100, 260, CV_8U, cv::Scalar(0));
    img(cv::Rect(2, 2, 76, 96)) = 255;     // room A
    img(cv::Rect(182, 2, 76, 96)) = 255;   // room B
    img(cv::Rect(78, 40, 104, 20)) = 255;  // corridor, 1 m wide
    const FreeSpace space = spaceOf(img);
    const VirtualDoor middle{{130, 39}, {130, 60}, 21, 1, {130, 50}};
    EXPECT_TRUE(DoorFilters().constriction(space, {middle}, 1.1).empty());
    DoorFilters::Options off;
    off.requireConstriction = false;
    EXPECT_EQ(DoorFilters(off).constriction(space, {middle}, 1.1).size(), 1u);

    const FreeSpace gap = spaceOf(twoRooms(0.9));
    const VirtualDoor door{{60, 30}, {60, 49}, 19, 1, {60, 40}};
    EXPECT_EQ(DoorFilters().constriction(gap, {door}, 1.1).size(), 1u);
}

TEST(DoorFilters, WallJambTestRejectsFreeStandingObstacles) {
    cv::Mat img(100, 100, CV_8U, cv::Scalar(0));
    img(cv::Rect(2, 2, 96, 96)) = 255;
    cv::circle(img, {40, 50}, 4, cv::Scalar(0), cv::FILLED);  // two chairs 1 m apart
    cv::circle(img, {64, 50}, 4, cv::Scalar(0), cv::FILLED);
    const FreeSpace space = spaceOf(img);
    const VirtualDoor between{{44, 50}, {60, 50}, 16, 0, {52, 50}};
    EXPECT_TRUE(DoorFilters().wallJambs(space, {between}, {}).empty());
    // A jamb on the outer wall passes, one on the chair does not.
    const VirtualDoor wallToChair{{1, 50}, {36, 50}, 35, 0, {20, 50}};
    EXPECT_TRUE(DoorFilters().wallJambs(space, {wallToChair}, {}).empty());
    DoorFilters::Options off;
    off.requireWallJambs = false;
    EXPECT_EQ(DoorFilters(off).wallJambs(space, {between}, {}).size(), 1u);
}

TEST(RegionBoundary, OpenIsUnobservedSpaceReachingTheMapsEdgeNotShadowsInside) {
    // The closet's door and the pocket's mouth cut (DrawnMaps.h, cabinetPocket).
    const auto drawn = toposlam::rooms::test::cabinetPocket();
    const FreeSpace space =
        FreeSpaceBinarizer().binarize(toposlam::rooms::test::gridOf(drawn.image));
    ASSERT_FALSE(space.noWall.empty());
    const auto px = [&](double x, double y) {
        return cv::Point(static_cast<int>(x / kRes),
                         drawn.image.rows - 1 - static_cast<int>(y / kRes));
    };
    const VirtualDoor closetDoor{px(6.62, 1.77), px(6.62, 2.73), 19, 0, px(6.62, 2.25)};
    const VirtualDoor mouth{px(4.17, 5.02), px(5.42, 5.02), 25, 0, px(4.8, 5.02)};
    const RegionPartition partition(space.free, {closetDoor, mouth});
    ASSERT_EQ(partition.regionCount(), 3);
    RegionBoundary boundary;
    boundary.measure(space, partition);
    const auto fraction = [&](int region) {
        const auto i = static_cast<std::size_t>(region);
        return static_cast<double>(boundary.open()[i]) /
               (boundary.open()[i] + boundary.closed()[i]);
    };
    const int room = partition.labels().at<int>(px(3, 3));
    const int closet = partition.labels().at<int>(px(7.9, 3.0));
    const int pocket = partition.labels().at<int>(px(4.8, 6.5));
    // The closet's third of unseen table shadow is enclosed by walls the laser saw: no opening.
    EXPECT_EQ(boundary.open()[static_cast<std::size_t>(closet)], 0);
    // Its walls without the door are 5.6 m long, the shadow's edges 3.2 m more.
    EXPECT_GT(boundary.closed()[static_cast<std::size_t>(closet)], 8 / kRes);
    // The pocket's flanks and the cabinets behind them reach the unknown outside.
    EXPECT_GT(fraction(pocket), 0.5);
    EXPECT_LT(fraction(room), 0.4);
}

TEST(WallThickness, RunsThroughUnknownCellsOnlyAreNoWalls) {
    // Walls 0.2 m (4 cells); each office, seen through its door only, is streaked with broken
    // one-cell lines of unknown cells between the beams: more one-cell runs than wall runs.
    const auto drawn = toposlam::rooms::test::officesSeenThroughTheirDoors();
    const FreeSpace space =
        FreeSpaceBinarizer().binarize(toposlam::rooms::test::gridOf(drawn.image));
    ASSERT_FALSE(space.unknown.empty());
    const Clearance clearance(space.free);
    WallThickness walls;
    walls.measure(space, clearance, 0.65);
    EXPECT_EQ(walls.mostFrequent(), 4);
    EXPECT_TRUE(walls.isWallThickness(4));
    EXPECT_FALSE(walls.isWallThickness(1));
    // The same cells drawn as a plan, every non-free cell a wall: the streaks are one-cell walls.
    FreeSpaceBinarizer::Options drawnPlan;
    drawnPlan.occupiedThreshold = 1;
    const FreeSpace plan =
        FreeSpaceBinarizer(drawnPlan).binarize(toposlam::rooms::test::gridOf(drawn.image));
    ASSERT_TRUE(plan.unknown.empty());
    walls.measure(plan, Clearance(plan.free), 0.65);
    EXPECT_EQ(walls.mostFrequent(), 1);
}

TEST(WallThickness, ToleratesTheSameCentimetresOnAFinerGrid) {
    // A 12 x 8 m plan drawn in 5 cm cells: walls 0.25 m thick, one 0.30 m; door gaps join the
    // rooms. The same plan in 2.5 cm cells must find the same walls: counted per cell, the
    // 0.30 m wall was two cells off the 0.25 m ones there, and no wall.
    cv::Mat coarse(160, 240, CV_8U, cv::Scalar(255));
    cv::rectangle(coarse, {0, 0}, {239, 159}, 0, 4);
    cv::rectangle(coarse, {80, 0}, {84, 159}, 0, cv::FILLED);    // 0.25 m
    cv::rectangle(coarse, {160, 0}, {164, 159}, 0, cv::FILLED);  // 0.25 m
    cv::rectangle(coarse, {0, 80}, {79, 84}, 0, cv::FILLED);     // 0.25 m
    cv::rectangle(coarse, {185, 80}, {239, 85}, 0, cv::FILLED);  // 0.30 m
    for (const cv::Rect door : {cv::Rect(80, 30, 5, 20), cv::Rect(80, 110, 5, 20),
                                cv::Rect(160, 30, 5, 20), cv::Rect(160, 110, 5, 20)}) {
        coarse(door) = 255;
    }
    cv::Mat fine;
    cv::resize(coarse, fine, {}, 2, 2, cv::INTER_NEAREST);
    for (const double res : {0.05, 0.025}) {
        SCOPED_TRACE(res);
        const cv::Mat& image = res == 0.05 ? coarse : fine;
        GridImageFrame frame = toposlam::rooms::test::frameOf(image);
        frame.resolution = res;
        const FreeSpace space = FreeSpaceBinarizer().binarize(image, frame);
        WallThickness walls;
        walls.measure(space, Clearance(space.free), 0.65);
        const auto cells = [res](double metres) { return metres / res; };
        EXPECT_NEAR(walls.mostFrequent(), cells(0.25), 0.5);
        EXPECT_TRUE(walls.isWallThickness(cells(0.25)));
        EXPECT_TRUE(walls.isWallThickness(cells(0.30)));
        EXPECT_FALSE(walls.isWallThickness(cells(0.60)));  // a cabinet against a wall
    }
}

TEST(FreeSpaceBinarizer, KeepsTheLargestFreeRegionAboveTheThreshold) {
    cv::Mat img(30, 40, CV_8U, cv::Scalar(128));
    img(cv::Rect(2, 2, 20, 20)) = 255;  // 400 cells
    img(cv::Rect(30, 2, 5, 5)) = 255;   // 25 cells, unreachable
    const auto grid = toposlam::rooms::test::gridOf(img);
    const FreeSpace space = FreeSpaceBinarizer().binarize(grid);
    EXPECT_EQ(space.freeCells, 400u);
    EXPECT_EQ(space.bounds, cv::Rect(2, 2, 20, 20));
    EXPECT_EQ(cv::countNonZero(space.otherFree), 25);
    EXPECT_NE(space.free.at<std::uint8_t>(10, 10), 0);  // image layout: row 0 = top
    // Unknown (0.5) is never free; a cell at p(free) 0.7 is free at 0.6, not at 0.8.
    auto g = grid;
    g.setCell(30, 0, 0.7f);
    const FreeSpace lower = FreeSpaceBinarizer({0.6}).binarize(g);
    EXPECT_EQ(cv::countNonZero(lower.otherFree), 26);
    // The smaller regions' runs are their cells, in raster order.
    cv::Mat painted = cv::Mat::zeros(lower.otherFree.size(), CV_8U);
    for (std::size_t k = 0; k < lower.otherFreeRuns.size(); ++k) {
        const ConnectedRuns::Run& run = lower.otherFreeRuns[k];
        if (k > 0) {
            const ConnectedRuns::Run& before = lower.otherFreeRuns[k - 1];
            EXPECT_TRUE(run.row > before.row || (run.row == before.row && run.begin > before.end));
        }
        painted.row(run.row).colRange(run.begin, run.end).setTo(255);
    }
    EXPECT_EQ(cv::countNonZero(painted != lower.otherFree), 0);
    EXPECT_EQ(cv::countNonZero(FreeSpaceBinarizer({0.8}).binarize(g).otherFree), 25);
}

// The obstacles are labelled in the free cells' bounding box only; they must still be the
// 8-connected non-free components of the whole map (the same partition, whatever the numbering),
// with "on the border" meaning "reaches the map's edge", also when free space touches the edge.
TEST(FreeSpaceBinarizer, EveryLogOddsValueIsFreeUnknownOrOccupiedByItsProbability) {
    // Every cell value a grid can hold, in rows of 37 cells (not a multiple of the sixteen cells
    // tested at a time), the top and bottom rows free so that the largest region exists.
    using Cell = mrpt::maps::COccupancyGridMap2D::cellType;
    mrpt::maps::COccupancyGridMap2D grid(0, 3.7f, 0, 1.0f, 0.1f);
    ASSERT_EQ(grid.getSizeX(), 37u);
    ASSERT_EQ(grid.getSizeY(), 10u);
    auto& raw = const_cast<std::vector<Cell>&>(grid.getRawMap());
    for (std::size_t i = 0; i < raw.size(); ++i) {
        const bool edge = i < 37 || i >= raw.size() - 37;
        raw[i] = edge ? std::numeric_limits<Cell>::max() : static_cast<Cell>(i * 7);
    }
    FreeSpaceBinarizer::Options options;
    options.maxSpeckArea = 0;  // no speck made free: free = p(free) above the threshold
    for (const double freeThreshold : {0.8, 0.98, 0.5, 0.3}) {
        options.freeThreshold = freeThreshold;
        const FreeSpace space = FreeSpaceBinarizer(options).binarize(grid);
        for (int y = 0; y < 10; ++y) {
            for (int x = 0; x < 37; ++x) {
                const double p = grid.getCell(x, y);
                const cv::Point cell(x, 9 - y);  // image layout: row 0 = top
                const bool free = space.free.at<std::uint8_t>(cell) != 0 ||
                                  space.otherFree.at<std::uint8_t>(cell) != 0;
                EXPECT_EQ(free, p > freeThreshold) << x << "," << y << " p " << p;
                const bool unknown = !space.unknown.empty() && space.unknown.at<std::uint8_t>(cell);
                EXPECT_EQ(unknown, p >= options.occupiedThreshold && p <= freeThreshold)
                    << x << "," << y << " p " << p;
            }
        }
    }
}

TEST(FreeSpaceBinarizer, AnUnknownSpeckMadeFreeIsNoLongerUnknown) {
    // A room of a SLAM grid: free inside, unknown outside, one unseen cell in the middle.
    cv::Mat img(30, 40, CV_8U, cv::Scalar(128));
    img(cv::Rect(2, 2, 30, 20)) = 0;
    img(cv::Rect(3, 3, 28, 18)) = 255;
    img.at<std::uint8_t>(10, 15) = 128;  // image layout: row 10, column 15
    const FreeSpace space = FreeSpaceBinarizer().binarize(toposlam::rooms::test::gridOf(img));
    EXPECT_EQ(space.specksRemoved, 1u);
    EXPECT_NE(space.free.at<std::uint8_t>(10, 15), 0);
    ASSERT_FALSE(space.unknown.empty());  // the unknown outside stays
    EXPECT_EQ(space.unknown.at<std::uint8_t>(10, 15), 0);
    EXPECT_NE(space.unknown.at<std::uint8_t>(25, 35), 0);
    EXPECT_EQ(cv::countNonZero(space.unknown & space.free), 0);
}

TEST(FreeSpaceBinarizer, AnUnseenHoleInTheFloorIsFreeAShadowBehindATableIsNot) {
    // A hall of a SLAM grid made with a short laser: free where the laser reached, unknown
    // outside; in the middle an island of unknown cells no ray reached and nothing bounds, and
    // a table (occupied) with the unknown shadow it casts.
    cv::Mat img(40, 60, CV_8U, cv::Scalar(128));
    img(cv::Rect(2, 2, 50, 30)) = 0;     // walls
    img(cv::Rect(3, 3, 48, 28)) = 255;   // floor
    img(cv::Rect(10, 10, 8, 10)) = 128;  // the unseen hole: 80 cells
    img(cv::Rect(35, 10, 3, 3)) = 0;     // the table
    img(cv::Rect(38, 10, 5, 3)) = 128;   // its shadow
    const auto grid = toposlam::rooms::test::gridOf(img);

    const FreeSpace space = FreeSpaceBinarizer().binarize(grid);
    EXPECT_EQ(space.unseenHolesFreed, 1u);
    EXPECT_EQ(space.unseenHoleCells, 80u);
    EXPECT_EQ(cv::countNonZero(space.free(cv::Rect(10, 10, 8, 10))), 80) << "the hole is floor";
    EXPECT_EQ(cv::countNonZero(space.unknown(cv::Rect(10, 10, 8, 10))), 0);
    EXPECT_EQ(cv::countNonZero(space.free(cv::Rect(35, 10, 8, 3))), 0) << "table and shadow stay";
    EXPECT_EQ(cv::countNonZero(space.unknown(cv::Rect(38, 10, 5, 3))), 15);
    EXPECT_NE(space.unknown.at<std::uint8_t>(36, 55), 0) << "the unknown outside stays";
    // The segmenter reports it, and toposlam-rooms' summary says so.
    const RoomSegmenter::Result result = RoomSegmenter().segment(grid);
    EXPECT_EQ(result.unseenHolesFreed, 1u);
    const double cell = grid.getResolution();
    EXPECT_NEAR(result.unseenHoleArea, 80 * cell * cell, 1e-9);
    EXPECT_NE(toposlam::rooms::describeRoomSegmentation(result, "hall")
                  .find("unseen holes in the floor counted as floor 1 ("),
              std::string::npos);

    FreeSpaceBinarizer::Options paper;
    paper.freeUnseenHoles = false;
    const FreeSpace kept = FreeSpaceBinarizer(paper).binarize(grid);
    EXPECT_EQ(kept.unseenHolesFreed, 0u);
    EXPECT_EQ(cv::countNonZero(kept.free(cv::Rect(10, 10, 8, 10))), 0);
    EXPECT_FALSE(RoomSegmenter::Options::paperExact().freeSpace.freeUnseenHoles);
}

TEST(FreeSpaceBinarizer, ObstaclesAreTheNonFreeComponentsOfTheWholeMap) {
    cv::RNG rng(7);
    for (int trial = 0; trial < 40; ++trial) {
        cv::Mat img(60, 70, CV_8U, cv::Scalar(0));
        // Random free boxes (some reaching the edges) with random obstacles and specks in them.
        for (int k = 0; k < 6; ++k) {
            const int x = rng.uniform(0, 60), y = rng.uniform(0, 50);
            const int height = rng.uniform(3, 60 - y), width = rng.uniform(3, 70 - x);
            img(cv::Rect(x, y, width, height)) = 255;
        }
        for (int k = 0; k < 25; ++k) {
            const int col = rng.uniform(0, 70), row = rng.uniform(0, 60);
            img.at<std::uint8_t>(row, col) = 0;
        }
        const FreeSpace space = spaceOf(img);
        cv::Mat notFree = space.obstacles != 0;  // after speck removal
        cv::Mat reference;
        const int n = cv::connectedComponents(notFree, reference, 8, CV_32S);
        std::vector<int> mine(static_cast<std::size_t>(n), -1);  // reference label -> ours
        std::vector<bool> touchesEdge(static_cast<std::size_t>(n), false);
        for (int r = 0; r < img.rows; ++r) {
            for (int c = 0; c < img.cols; ++c) {
                const auto ref = static_cast<std::size_t>(reference.at<int>(r, c));
                const int ours = space.obstacles.at<int>(r, c);
                ASSERT_EQ(ref == 0, ours == 0) << "trial " << trial;
                if (ref == 0)
                    continue;
                if (mine[ref] < 0)
                    mine[ref] = ours;
                ASSERT_EQ(mine[ref], ours) << "trial " << trial << " cell " << r << "," << c;
                if (r == 0 || c == 0 || r == img.rows - 1 || c == img.cols - 1)
                    touchesEdge[ref] = true;
            }
        }
        std::set<int> distinct;
        for (int i = 1; i < n; ++i) {
            distinct.insert(mine[static_cast<std::size_t>(i)]);
            EXPECT_EQ(space.obstacleOnBorder[static_cast<std::size_t>(
                          mine[static_cast<std::size_t>(i)])] != 0,
                      touchesEdge[static_cast<std::size_t>(i)])
                << "trial " << trial;
        }
        EXPECT_EQ(distinct.size(), static_cast<std::size_t>(n - 1)) << "trial " << trial;
        // The island runs are the cells of the obstacles off the border, each cell once.
        cv::Mat islands = cv::Mat::zeros(img.size(), CV_32S);
        for (const auto& run : space.islandRuns) {
            for (int c = run.begin; c < run.end; ++c) {
                ASSERT_EQ(islands.at<int>(run.row, c), 0) << "trial " << trial;
                islands.at<int>(run.row, c) = run.label;
            }
        }
        for (int r = 0; r < img.rows; ++r) {
            for (int c = 0; c < img.cols; ++c) {
                const int ours = space.obstacles.at<int>(r, c);
                const bool island =
                    ours != 0 && !space.obstacleOnBorder[static_cast<std::size_t>(ours)];
                ASSERT_EQ(islands.at<int>(r, c), island ? ours : 0)
                    << "trial " << trial << " cell " << r << "," << c;
            }
        }
    }
}

namespace {

// Labels of a 6 x 4 m room (id 1) beside a 2 m corridor (id 2), both inside 0.1 m walls, a
// 0.2 m wall between them (wall cells 0); `notches`: non-free rectangles cut out of the room.
cv::Mat roomBesideCorridor(const std::vector<cv::Rect>& notches) {
    cv::Mat labels(84, 168, CV_32S, cv::Scalar(0));
    labels(cv::Rect(2, 2, 120, 80)) = 1;
    labels(cv::Rect(126, 2, 40, 80)) = 2;
    for (const cv::Rect& r : notches)
        labels(r) = 0;
    return labels;
}

int countLabel(const cv::Mat& labels, const cv::Rect& area, int label) {
    return cv::countNonZero(labels(area) == label);
}

}  // namespace

TEST(FurniturePockets, CornerAndWallFurnitureJoinTheRoomWallsDoNot) {
    const cv::Rect cornerDesk(2, 2, 32, 16);  // 1.6 x 0.8 m in the top left corner
    const cv::Rect cabinet(50, 72, 24, 10);   // 1.2 x 0.5 m against the bottom wall
    const cv::Rect longShelf(2, 30, 8, 52);   // 2.6 m along the left wall: longer than 2 m
    cv::Mat labels = roomBesideCorridor({cornerDesk, cabinet, longShelf});
    const cv::Mat before = labels.clone();
    FurniturePockets pockets;
    const std::size_t n = pockets.label({}, 0.0, {}, kRes, labels);
    // The room's box is one cell in from its outermost lines (a wall drawn at an angle has steps
    // a cell deep): the furniture's line along the wall stays out.
    EXPECT_EQ(countLabel(labels, cornerDesk, 1), 31 * 15);
    EXPECT_EQ(countLabel(labels, cabinet, 1), 24 * 9);
    EXPECT_EQ(countLabel(labels, longShelf, 0), longShelf.area());
    EXPECT_EQ(n, static_cast<std::size_t>(31 * 15 + 24 * 9));
    EXPECT_EQ(cv::countNonZero(labels != before), static_cast<int>(n));
    EXPECT_EQ(countLabel(labels, cv::Rect(0, 0, 168, 2), 0), 2 * 168) << "walls stay unlabelled";
    EXPECT_EQ(countLabel(labels, cv::Rect(122, 0, 4, 84), 0), 4 * 84);
}

TEST(FurniturePockets, NoPocketBetweenTwoRoomsOrBeyondADoorOrRoundACurvedEnd) {
    // An L-shaped room round a small room: the L's box holds the small room and the walls
    // between the two, which touch the small room: walls, not furniture.
    cv::Mat labels = roomBesideCorridor({});
    labels(cv::Rect(62, 2, 60, 40)) = 0;
    labels(cv::Rect(66, 2, 56, 36)) = 3;
    cv::Mat before = labels.clone();
    FurniturePockets pockets;
    pockets.label({}, 0.0, {}, kRes, labels);
    EXPECT_EQ(cv::countNonZero(labels != before), 0);

    // A 1.4 m door from a 3 x 1.8 m room to a corridor through a 0.2 m wall: the room's half of
    // the opening must not stretch the room's box over the wall, nor the wall along the room
    // become a pocket.
    labels = cv::Mat(40, 110, CV_32S, cv::Scalar(0));
    labels(cv::Rect(2, 2, 60, 36)) = 1;
    labels(cv::Rect(66, 2, 40, 36)) = 2;
    labels(cv::Rect(62, 6, 2, 28)) = 1;
    labels(cv::Rect(64, 6, 2, 28)) = 2;
    VirtualDoor door;
    door.jambA = {63, 5};
    door.jambB = {63, 34};
    door.width = 29;
    before = labels.clone();
    pockets.label({}, 0.0, {door}, kRes, labels);
    EXPECT_EQ(cv::countNonZero(labels != before), 0);
    // Without the door, the half opening (28 of the room's 36 cells across) is taken for a side
    // of the room: the check above would fail.
    pockets.label({}, 0.0, {}, kRes, labels);
    EXPECT_GT(cv::countNonZero(labels != before), 0);

    // A room whose far end is a half circle: the corners beside it fill less than half their box.
    labels = cv::Mat(84, 144, CV_32S, cv::Scalar(0));
    labels(cv::Rect(2, 2, 100, 80)) = 1;
    cv::circle(labels, {101, 41}, 40, cv::Scalar(1), cv::FILLED);
    before = labels.clone();
    pockets.label({}, 0.0, {}, kRes, labels);
    EXPECT_EQ(cv::countNonZero(labels != before), 0);
}

TEST(FurniturePockets, OnRandomLabelsOnlyUnlabelledCellsChangeAndNoPocketTouchesAnotherRoom) {
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> coordinate(0, 99), extent(3, 40), room(1, 5);
    std::uniform_real_distribution<double> angle(0, M_PI);
    FurniturePockets pockets;
    std::size_t labelled = 0;
    for (int trial = 0; trial < 200; ++trial) {
        cv::Mat labels(100, 100, CV_32S, cv::Scalar(0));
        for (int k = 0; k < 12; ++k) {  // rooms and obstacles drawn over each other
            const int h = extent(rng), w = extent(rng);  // one draw per statement
            const int y = coordinate(rng), x = coordinate(rng);
            const cv::Rect r(x, y, w, h);
            labels(r & cv::Rect(0, 0, 100, 100)) = k % 3 == 2 ? 0 : room(rng);
        }
        std::vector<VirtualDoor> doors(1);
        doors[0].jambA = {coordinate(rng), coordinate(rng)};
        doors[0].jambB = doors[0].jambA + cv::Point(0, 20);
        doors[0].width = 20;
        const cv::Mat before = labels.clone();
        const std::size_t n = pockets.label({}, angle(rng), doors, kRes, labels);
        ASSERT_EQ(cv::countNonZero(labels != before), static_cast<int>(n));
        labelled += n;
        for (int y = 0; y < labels.rows; ++y) {
            for (int x = 0; x < labels.cols; ++x) {
                const int now = labels.at<int>(y, x), was = before.at<int>(y, x);
                if (now == was)
                    continue;
                ASSERT_EQ(was, 0) << "a labelled cell changed";
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        const cv::Point q(x + dx, y + dy);
                        if (q.x < 0 || q.y < 0 || q.x >= 100 || q.y >= 100)
                            continue;
                        const int l = labels.at<int>(q);
                        ASSERT_TRUE(l == 0 || l == now) << "a pocket touches another room";
                    }
                }
            }
        }
    }
    EXPECT_GT(labelled, 0u) << "no trial had a pocket: the checks above saw nothing";
}
