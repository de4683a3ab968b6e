// toposlam-plan end to end on the bundled office: both topological-map formats toposlam-rooms
// writes plan alike, and every kind of failure has its exit status (1 bad input, 2 bad usage,
// 3 no path) and writes nothing.
#include <TestSupport.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <string>

using toposlam::test::quoted;
using toposlam::test::runApp;
using toposlam::test::TempDir;

namespace {

const std::string kMap = toposlam::test::shareDir() + "/office/office.gridmap.gz";

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

TEST(PlanApp, ABarePlanPictureIsReadAsTheRoomsWereAndThePathKeepsToWhite) {
    // Two white rooms behind light-grey walls (211: p(free) 0.83, free at the planner's 0.6
    // were the picture read as a grid) in a grey background, joined by a 1 m door, given bare.
    // toposlam-rooms and toposlam-plan both take it for a drawn plan: the path goes through
    // the door, every point of it on white.
    const TempDir dir;
    cv::Mat plan(100, 200, CV_8U, cv::Scalar(180));
    cv::rectangle(plan, cv::Rect(10, 10, 180, 80), cv::Scalar(211), cv::FILLED);
    cv::rectangle(plan, cv::Rect(14, 14, 172, 72), cv::Scalar(255), cv::FILLED);
    cv::rectangle(plan, cv::Rect(98, 14, 4, 72), cv::Scalar(211), cv::FILLED);
    cv::rectangle(plan, cv::Rect(98, 64, 4, 20), cv::Scalar(255), cv::FILLED);  // off the line
    const std::string picture = dir.file("plan.png");
    ASSERT_TRUE(cv::imwrite(picture, plan));
    auto r = runApp("toposlam-rooms", quoted(picture) + " -q -o " + quoted(dir.file("rooms")));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runApp("toposlam-plan", quoted(picture) + " " + quoted(dir.file("rooms/rooms.json")) +
                                    " --from 1 --to 2 -o " + quoted(dir.file("plan")));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("read as a drawn floor plan"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("route: room 1 -> door 1 -> room 2"), std::string::npos) << r.output;
    std::istringstream path(readFile(dir.file("plan/path.txt")));
    std::vector<cv::Point2d> points;
    for (std::string line; std::getline(path, line);) {
        double x = 0, y = 0;
        if (!line.empty() && line[0] != '#' && std::istringstream(line) >> x >> y)
            points.emplace_back(x, y);
    }
    ASSERT_GE(points.size(), 2u);
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        // Along each leg every centimetre (cells of 5 cm, origin at the lower left).
        const int steps = static_cast<int>(std::ceil(cv::norm(points[i + 1] - points[i]) / 0.01));
        for (int k = 0; k <= steps; ++k) {
            const cv::Point2d p = points[i] + (points[i + 1] - points[i]) * (double(k) / steps);
            const int col = static_cast<int>(std::floor(p.x / 0.05));
            const int row = plan.rows - 1 - static_cast<int>(std::floor(p.y / 0.05));
            ASSERT_TRUE(col >= 0 && col < plan.cols && row >= 0 && row < plan.rows);
            EXPECT_EQ(plan.at<unsigned char>(row, col), 255) << "(" << p.x << ", " << p.y << ")";
        }
    }
    r = runApp("toposlam-plan", quoted(picture) + " " + quoted(dir.file("rooms/rooms.json")) +
                                    " --from 1 --to 2 --drawn --grid -o " +
                                    quoted(dir.file("both")));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("both")));
}

// An output folder that cannot be made is an error before planning (no route printed), said
// as toposlam-slam and toposlam-rooms say it.
TEST(PlanApp, AnOutputFolderThatCannotBeMadeIsAnErrorBeforePlanning) {
    const TempDir dir;
    toposlam::test::writeText(dir.file("afile"), "x");
    for (const std::string& out : {dir.file("afile"), dir.file("afile/plan")}) {
        const auto r =
            runApp("toposlam-plan", quoted(kMap) + " " + quoted(roomsDir() + "/rooms.json") +
                                        " --from 1 --to 3 -o " + quoted(out));
        EXPECT_EQ(r.exitCode, 1) << r.output;
        EXPECT_NE(r.output.find("error: " + out + ": cannot create the output folder"),
                  std::string::npos)
            << r.output;
        EXPECT_EQ(r.output.find("length:"), std::string::npos) << "planned first\n" << r.output;
        EXPECT_EQ(r.output.find("filesystem error"), std::string::npos) << r.output;
    }
}
