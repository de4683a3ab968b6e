// B4-rings: the virtual-door segmenter on generated buildings around a corridor ring
// (simulation::generateFloorPlan, BuildingStyle::Ring), scored against their exact ground truth
// like Bormann's maps. The corridor loops round the middle block, and rows of rooms that look
// alike line it on both sides: each must come out a room of its own, the ring one room.
#include <toposlam/rooms/RoomBenchmark.h>
#include <toposlam/roomsbench/GeneratedRoomCases.h>

#include <gtest/gtest.h>

#include <cstddef>

using namespace toposlam;

TEST(Rings, EveryRoomAlongTheRingIsARoomAndEveryDoorIsFound) {
    rooms::RoomBenchmarkOptions o;
    o.repeats = 1;
    o.methods = {"vdoor"};
    const rooms::RoomBenchmark bench(o);
    for (unsigned seed = 1; seed <= 5; ++seed) {
        for (const auto& c :
             roomsbench::generatedCases(seed, {0}, simulation::BuildingStyle::Ring)) {
            SCOPED_TRACE(c.map);
            for (const rooms::RoomBenchmarkScore& s : bench.score(c)) {
                // As many segments as rooms give or take one, almost every room's floor in its
                // own segment (furniture hides a few per cent of it), no segment across two.
                EXPECT_NEAR(double(s.pr.segments), double(s.pr.rooms), 1.0);
                EXPECT_GE(s.pr.recall, c.furnished ? 0.95 : 0.99);
                EXPECT_GE(s.pr.precision, 0.98);
                // Walls only: no room, the ring included, cut in parts. (Furnished, one false
                // door may cut a room: in ring01 a lab, from a partition stub's end to a cabinet.)
                for (std::size_t g = 0; !c.furnished && g < s.pr.roomRecall.size(); ++g)
                    EXPECT_GE(s.pr.roomRecall[g], 0.95) << "room " << g + 1;
                EXPECT_EQ(s.doors.matchedTrue, s.doors.trueDoors);
                EXPECT_LE(s.doors.virtualDoors - s.doors.matchedVirtual, 1u);
            }
        }
    }
}
