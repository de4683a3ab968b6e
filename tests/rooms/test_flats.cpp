// B4-flats: the virtual-door segmenter on generated flats (simulation::generateFloorPlan,
// BuildingStyle::Flat), scored against their exact ground truth like Bormann's maps. No corridor:
// rooms open into rooms, doors sit next to corners, and beds, wardrobes and sofas stand against
// inner walls.
#include <toposlam/rooms/RoomBenchmark.h>
#include <toposlam/roomsbench/GeneratedRoomCases.h>

#include <gtest/gtest.h>

#include <cstddef>

using namespace toposlam;
using rooms::RoomBenchmarkScore;

namespace {

struct FlatTotals {
    std::size_t trueDoors = 0, matchedTrue = 0, virtualDoors = 0, matchedVirtual = 0;
    double recallSum = 0;
    std::size_t maps = 0;
    std::size_t falseDoors() const { return virtualDoors - matchedVirtual; }
};

// The 20 B4-flats plans, furnished or not, segmented by vdoor with `options`, in cells of
// `cellSize` m (0: as drawn), as the benchmark maps them (RoomBenchmark::atCellSize).
FlatTotals flats(bool furnished, const rooms::RoomSegmenter::Options& options,
                 double cellSize = 0) {
    rooms::RoomBenchmarkOptions o;
    o.repeats = 1;
    o.methods = {"vdoor"};
    o.virtualDoor = options;
    o.cellSize = cellSize;
    const rooms::RoomBenchmark bench(o);
    FlatTotals t;
    for (const unsigned seed : roomsbench::b4GenSeeds()) {
        for (const auto& c : bench.atCellSize(
                 roomsbench::generatedCases(seed, {0}, simulation::BuildingStyle::Flat))) {
            if (c.furnished != furnished)
                continue;
            for (const RoomBenchmarkScore& s : bench.score(c)) {
                t.trueDoors += s.doors.trueDoors;
                t.matchedTrue += s.doors.matchedTrue;
                t.virtualDoors += s.doors.virtualDoors;
                t.matchedVirtual += s.doors.matchedVirtual;
                t.recallSum += s.pr.recall;
                ++t.maps;
            }
        }
    }
    return t;
}

}  // namespace

// Walls only: every room is found whole and no door is invented (a door beside a corner, an
// open kitchen up to 2.4 m wide, rooms reached only through other rooms).
TEST(Flats, UnfurnishedFlatsAreSegmentedRoomForRoom) {
    const FlatTotals t = flats(false, rooms::RoomSegmenter::Options::improved());
    ASSERT_EQ(t.maps, 20u);
    EXPECT_GE(t.recallSum / double(t.maps), 0.99);
    EXPECT_EQ(t.falseDoors(), 0u);
    EXPECT_GE(double(t.matchedTrue), 0.9 * double(t.trueDoors));
}

// In 2.5 cm cells, the walls and doors of the same flats drawn finer: as many doors found, none
// invented. A jamb on a wall's face is found within 0.1 m across the wall (two cells of 5 cm):
// counted as two cells there, doors a hand's width from a corner were lost (126 of 138 found
// instead of 132).
TEST(Flats, FinerCellsFindTheSameDoors) {
    const auto options = rooms::RoomSegmenter::Options::improved();
    const FlatTotals drawn = flats(false, options), fine = flats(false, options, 0.025);
    ASSERT_EQ(fine.maps, 20u);
    EXPECT_EQ(fine.trueDoors, drawn.trueDoors);
    EXPECT_GE(fine.matchedTrue + 1, drawn.matchedTrue);
    EXPECT_EQ(fine.falseDoors(), 0u);
}

// A bed with its head to an inner wall, seen from its side, is an obstacle with free space on
// one side only within twice the thickest wall: it used to pass for the end of an outer wall
// (the edge of the mapped space) and frame false doors in the gaps beside it. With edge_depth the
// next room behind it shows, and those doors go; no true door goes with them.
TEST(Flats, FurnitureAgainstAnInnerWallIsNoWallEnd) {
    rooms::RoomSegmenter::Options withDepth = rooms::RoomSegmenter::Options::improved();
    rooms::RoomSegmenter::Options without = withDepth;
    without.filters.edgeDepth = 0;  // at most 2 x max_wall_thickness: off
    const FlatTotals a = flats(true, withDepth), b = flats(true, without);
    EXPECT_LT(2 * a.falseDoors(), b.falseDoors());
    EXPECT_GE(a.matchedTrue, b.matchedTrue);
    EXPECT_GT(a.recallSum, b.recallSum);
}

// A 2.1 m bed or a 2.4 m wardrobe against a wall is furniture of its room (its cells count to the
// room, as the ground truth counts them): with pockets up to 2.0 m they stayed nobody's and the
// furnished flats' recall was lower, doors the same.
TEST(Flats, BedsAndWardrobesAgainstWallsBelongToTheirRooms) {
    const rooms::RoomSegmenter::Options defaults = rooms::RoomSegmenter::Options::improved();
    rooms::RoomSegmenter::Options shorter = defaults;
    shorter.maxFurnitureSize = 2.0;
    const FlatTotals a = flats(true, defaults), b = flats(true, shorter);
    EXPECT_GT(a.recallSum / double(a.maps), b.recallSum / double(b.maps) + 0.005);
    EXPECT_EQ(a.matchedTrue, b.matchedTrue);
    EXPECT_EQ(a.falseDoors(), b.falseDoors());
}
