// toposlam-plan end to end on the bundled office: both topological-map formats toposlam-rooms
// writes plan alike, and every kind of failure has its exit status (1 bad input, 2 bad usage,
// 3 no path) and writes nothing.
#include <TestSupport.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

using toposlam::test::runApp;
using toposlam::test::TempDir;

namespace {

const std::string kMap = toposlam::test::shareDir() + "/office/office.gridmap.gz";

std::string quoted(const std::string& s) {
    return "'" + s + "'";
}

using toposlam::test::readFile;

// rooms.json and rooms.graphml of the office, segmented once for all tests.
const std::string& roomsDir() {
    static const TempDir dir;
    static const bool made = [] {
        const auto r = runApp("toposlam-rooms", quoted(kMap) + " -q -o " + quoted(dir.path()));
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return true;
    }();
    (void)made;
    return dir.path();
}

struct Plan {
    int exitCode;
    std::string output;
    std::string folder;
};

Plan plan(const TempDir& dir, const std::string& rooms, const std::string& options) {
    const std::string out = dir.file("plan");
    const auto r = runApp(
        "toposlam-plan", quoted(kMap) + " " + quoted(rooms) + " " + options + " -o " + quoted(out));
    return {r.exitCode, r.output, out};
}

}  // namespace

TEST(PlanApp, JsonAndGraphMLFromToposlamRoomsBothPlan) {
    const TempDir dir;
    std::string routes[2];
    int k = 0;
    for (const char* file : {"rooms.json", "rooms.graphml"}) {
        const Plan p = plan(dir, roomsDir() + "/" + file, "--from 1 --to farthest --seed 3");
        ASSERT_EQ(p.exitCode, 0) << file << "\n" << p.output;
        EXPECT_NE(p.output.find("route: room 1 -> door"), std::string::npos) << p.output;
        const std::string path = readFile(p.folder + "/path.txt");
        EXPECT_NE(path.find("# length_m: "), std::string::npos) << path;
        EXPECT_TRUE(std::filesystem::is_regular_file(p.folder + "/path.png"));
        routes[k++] = p.output.substr(0, p.output.find("length"));
        std::filesystem::remove_all(p.folder);
    }
    EXPECT_EQ(routes[0], routes[1]) << "the same rooms, doors and route from either format";
}

TEST(PlanApp, EachFailureHasItsExitStatusAndWritesNothing) {
    const TempDir dir;
    const std::string json = roomsDir() + "/rooms.json";
    // Rooms of another map (the office image read with another cell size): bad input.
    const auto other =
        runApp("toposlam-rooms", quoted(toposlam::test::shareDir() + "/office/office.png") +
                                     " --resolution 0.1 -q -o " + quoted(dir.file("other")));
    ASSERT_EQ(other.exitCode, 0) << other.output;
    // A GraphML graph without the map geometry (another writer's): bad input, said so.
    std::string graph = readFile(roomsDir() + "/rooms.graphml");
    for (const std::string key : {"cols", "rows", "label_runs"}) {
        const std::string open = "<data key=\"" + key + "\">";
        for (auto at = graph.find(open); at != std::string::npos; at = graph.find(open))
            graph.erase(at, graph.find("</data>", at) + 7 - at);
    }
    std::ofstream(dir.file("bare.graphml")) << graph;
    const struct {
        std::string rooms, options, expected;
        int exitCode;
    } cases[] = {
        {dir.file("other/rooms.json"), "--from 1 --to 2", "segmented from another map", 1},
        {dir.file("bare.graphml"), "--from 1 --to 2", "no room cells", 1},
        {dir.file("missing.json"), "--from 1 --to 2", "missing.json", 1},
        {json, "--from 99 --to 2", "error: --from: no room with id 99", 2},
        {json, "--from 1 --to kitchen", "error: --to: no room named 'kitchen'", 2},
        {json, "--from 1 --to 2 --attempts -1", "error: --attempts: '-1'", 2},
        {json, "--from 1 --to 2 --planner astar", "error: --planner", 2},
        {json, "--from 1 --to 2 --robot-radius 5", "no path: the robot does not fit", 3},
    };
    for (const auto& c : cases) {
        const Plan p = plan(dir, c.rooms, c.options);
        EXPECT_EQ(p.exitCode, c.exitCode) << c.options << "\n" << p.output;
        EXPECT_NE(p.output.find(c.expected), std::string::npos) << c.options << "\n" << p.output;
        EXPECT_FALSE(std::filesystem::exists(p.folder)) << c.options << ": wrote output";
    }
}
