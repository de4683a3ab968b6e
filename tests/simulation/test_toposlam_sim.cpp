// toposlam-sim end to end, and the share/office data set it makes.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/simulation/GridGeometry.h>
#include <toposlam/simulation/OfficeFloorPlan.h>
#include <toposlam/simulation/SimulatorConfig.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <sstream>

#include "SimulationTestMaps.h"
#include "TestSupport.h"

using namespace toposlam;
using namespace toposlam::simulation;
using toposlam::test::quoted;
using toposlam::test::runApp;
using toposlam::test::TempDir;
namespace fs = std::filesystem;

namespace {

using toposlam::test::writeText;

/// Two 4 m x 3 m rooms joined by a 0.9 m door: a small map for quick tours.
FloorPlan twoRooms() {
    FloorPlan plan;
    const double t = 0.1, o = t / 2;
    plan.addWall({-o, -o}, {8.1 + o, -o}, t);
    plan.addWall({-o, 3 + o}, {8.1 + o, 3 + o}, t);
    plan.addWall({-o, -o}, {-o, 3 + o}, t);
    plan.addWall({8.1 + o, -o}, {8.1 + o, 3 + o}, t);
    plan.addWall({4.05, 0}, {4.05, 3}, t);
    const int a = plan.addRoom("west", "room", {0, 0, 4, 3});
    const int b = plan.addRoom("east", "room", {4.1, 0, 8.1, 3});
    plan.addDoor({4.05, 1.0}, {4.05, 1.9}, a, b);
    return plan;
}

std::string officeMap() {
    return toposlam::test::shareDir() + "/office/office.gridmap.gz";
}

}  // namespace

TEST(ToposlamSim, HelpExplainsEveryOption) {
    const auto r = runApp("toposlam-sim", "--help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* option :
         {"--poses",          "--tour",       "--make-office", "--out",
          "--format",         "--gt",         "--config",      "--beams",
          "--fov-deg",        "--max-range",  "--range-noise", "--bearing-noise-deg",
          "--exact-odometry", "--people",     "--seed",        "--start",
          "--plot",           "--resolution", "--origin",      "--quiet",
          "--drawn"}) {
        EXPECT_NE(r.output.find(option), std::string::npos) << option;
    }
    EXPECT_NE(r.output.find("Default: 361"), std::string::npos);
}

TEST(ToposlamSim, TourOnASmallMapWritesARawlogAndItsGroundTruth) {
    TempDir dir;
    io::saveGridMap(twoRooms().rasterise(0.05, 0.3), dir.file("rooms.gridmap.gz"));
    const auto r = runApp("toposlam-sim", quoted(dir.file("rooms.gridmap.gz")) + " --tour -o " +
                                              quoted(dir.file("out.rawlog")) + " --plot " +
                                              quoted(dir.file("tour.png")));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto records = io::LaserLogReader::readAll(dir.file("out.rawlog"));
    const auto gt = io::loadTrajectory(dir.file("out_gt.txt"));  // the default name
    ASSERT_GT(records.size(), 10u);
    ASSERT_EQ(records.size(), gt.size());
    std::set<int> rooms;
    const FloorPlan plan = twoRooms();
    for (std::size_t i = 0; i < gt.size(); ++i) {
        EXPECT_EQ(records[i].fileStamp, gt[i].stamp);
        rooms.insert(plan.roomAt({gt[i].pose.x, gt[i].pose.y}));
    }
    EXPECT_TRUE(rooms.count(1) && rooms.count(2)) << "the tour visits both rooms";
    const auto& scan = *records[0].scan;
    EXPECT_EQ(scan.getScanSize(), 361u);
    EXPECT_NEAR(scan.aperture, 1.5 * M_PI, 1e-6);
    EXPECT_EQ(scan.sensorLabel, "LASER");
    EXPECT_NEAR(scan.sensorPose.x(), 0.2, 1e-9);
    EXPECT_TRUE(fs::exists(dir.file("tour.png")));
}

/// A floor plan as drawn (Bormann's maps): white rooms, black walls and a grey (190) background
/// around the building, 16 x 11 m at 0.05 m per pixel. Two 4 x 3 m rooms ([4.1, 8.05] and
/// [8.15, 12.1] x [4.1, 7.1] m) with a 0.9 m door between them; the west room opens on to the
/// background by a 2 m wide entrance; a grey (200) table 0.8 m square stands in the east room at
/// x [10.5, 11.3], y [4.5, 5.3] m.
void writeDrawnPlan(const std::string& path) {
    constexpr double res = 0.05, height = 11.0;
    cv::Mat image(static_cast<int>(height / res), static_cast<int>(16.0 / res), CV_8U,
                  cv::Scalar(190));
    const auto box = [&](double x0, double y0, double x1, double y1, int grey) {
        const cv::Point a(static_cast<int>(std::lround(x0 / res)),
                          static_cast<int>(std::lround((height - y1) / res)));
        const cv::Point b(static_cast<int>(std::lround(x1 / res)),
                          static_cast<int>(std::lround((height - y0) / res)));
        image(cv::Rect(a, b)).setTo(grey);
    };
    box(4.0, 4.0, 12.2, 7.2, 0);     // outer walls ...
    box(4.1, 4.1, 12.1, 7.1, 255);   // ... round the floor
    box(8.05, 4.1, 8.15, 7.1, 0);    // the wall between the rooms ...
    box(8.05, 5.1, 8.15, 6.0, 255);  // ... and its door
    box(4.0, 4.6, 4.1, 6.6, 255);    // the entrance
    box(10.5, 4.5, 11.3, 5.3, 200);  // the table
    ASSERT_TRUE(cv::imwrite(path, image));
}

TEST(ToposlamSim, DrawnPlanIsReadAsOneToursTheBuildingAndItsFurnitureStopsTheLaser) {
    TempDir dir;
    writeDrawnPlan(dir.file("plan.png"));
    const std::string plan = quoted(dir.file("plan.png"));
    // Read as p(free) = grey / 255 (--grid) the background is free: with the west room it is
    // one area open to the map's edge, so the tour keeps to the east room and says why.
    auto r = runApp("toposlam-sim", plan + " --tour --grid -o " + quoted(dir.file("grey.rawlog")));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("warning: the tour drives only"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("try --drawn"), std::string::npos) << r.output;

    // Without --grid or --drawn the picture, white rooms in grey walls and background, is taken
    // for a drawn plan, and says so.
    r = runApp("toposlam-sim", plan + " --tour -o " + quoted(dir.file("drawn.rawlog")));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("read as a drawn floor plan"), std::string::npos) << r.output;
    bool west = false, east = false;
    for (const auto& p : io::loadTrajectory(dir.file("drawn_gt.txt"))) {
        ASSERT_TRUE(p.pose.x > 4.1 && p.pose.x < 12.1 && p.pose.y > 4.1 && p.pose.y < 7.1)
            << "pose (" << p.pose.x << ", " << p.pose.y << ") outside the building";
        west = west || p.pose.x < 8.05;
        east = east || p.pose.x > 8.15;
    }
    EXPECT_TRUE(west && east) << "both rooms";

    // The laser (0.2 m ahead of the robot) looks from x = 9.5 m straight at the table, 1.0 m
    // ahead: read as a drawn plan it stops there (--drawn, or the guess without an option);
    // read as grey / 255 (--grid) it sees through to the east wall.
    writeText(dir.file("pose.txt"), "1 9.3 4.9 0\n2 9.3 4.9 0\n");
    for (const char* reading : {" --drawn", "", " --grid"}) {
        const bool drawn = std::string(reading) != " --grid";
        const std::string out = dir.file("table" + std::string(reading) + ".rawlog");
        r = runApp("toposlam-sim", plan + " --poses " + quoted(dir.file("pose.txt")) +
                                       " --exact-odometry --range-noise 0 --bearing-noise-deg 0" +
                                       reading + " -o " + quoted(out));
        ASSERT_EQ(r.exitCode, 0) << r.output;
        const auto records = io::LaserLogReader::readAll(out);
        ASSERT_EQ(records.size(), 2u);
        const auto& scan = *records[0].scan;
        const float ahead = scan.getScanRange(scan.getScanSize() / 2);
        EXPECT_NEAR(ahead, drawn ? 1.0 : 2.6, 0.06) << "reading:" << reading;
    }
}

TEST(ToposlamSim, CommandLineOverridesTheConfigFile) {
    TempDir dir;
    writeText(dir.file("sim.ini"),
              "[Laser]\nbeams = 100\nfov_deg = 90\n[Simulation]\nformat = sf\n");
    writeText(dir.file("poses.txt"), "# t x y yaw\n10 2 6.5 0\n10.5 2.3 6.5 0\n11 2.6 6.5 0.1\n");
    const auto r =
        runApp("toposlam-sim", quoted(officeMap()) + " --poses " + quoted(dir.file("poses.txt")) +
                                   " -o " + quoted(dir.file("run.rawlog.gz")) + " -c " +
                                   quoted(dir.file("sim.ini")) + " --beams 181 --gt " +
                                   quoted(dir.file("gt.txt")));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    io::LaserLogReader reader(dir.file("run.rawlog.gz"));
    EXPECT_EQ(reader.format(), io::LaserLogFormat::RawlogSensoryFrames);
    io::LaserLogRecord rec;
    std::size_t n = 0;
    while (reader.next(rec)) {
        EXPECT_EQ(rec.scan->getScanSize(), 181u) << "--beams beats the file";
        EXPECT_NEAR(rec.scan->aperture, M_PI / 2, 1e-6) << "the file beats the default";
        ++n;
    }
    EXPECT_EQ(n, 3u);
    const auto gt = io::loadTrajectory(dir.file("gt.txt"));
    ASSERT_EQ(gt.size(), 3u);
    EXPECT_EQ(gt[2].stamp, 11.0);
    EXPECT_EQ(gt[2].pose.phi, 0.1);
}

TEST(ToposlamSim, BadInputGivesAClearErrorAndNoOutput) {
    TempDir dir;
    const std::string out = dir.file("out.rawlog");
    mrpt::maps::COccupancyGridMap2D walls(0.0f, 3.0f, 0.0f, 3.0f, 0.05f);
    walls.fill(0.0f);
    io::saveGridMap(walls, dir.file("walls.gridmap.gz"));
    writeText(dir.file("malformed.txt"), "1 2 6.5 0\n2 2.5 six 0\n");
    writeText(dir.file("backwards.txt"), "1 2 6.5 0\n2 2.5 6.5 0\n1.5 3 6.5 0\n");
    writeText(dir.file("outside.txt"), "1 2 6.5 0\n2 200 6.5 0\n");
    struct Case {
        std::string args, expected;
    };
    const std::vector<Case> cases = {
        {quoted(dir.file("missing.gridmap.gz")) + " --tour", "missing.gridmap.gz"},
        {quoted(dir.file("walls.gridmap.gz")) + " --tour", "free"},
        {quoted(dir.file("walls.gridmap.gz")) + " --poses " + quoted(dir.file("backwards.txt")),
         "free"},
        {quoted(officeMap()) + " --poses " + quoted(dir.file("malformed.txt")), "malformed.txt"},
        {quoted(officeMap()) + " --poses " + quoted(dir.file("backwards.txt")), "increase"},
        {quoted(officeMap()) + " --poses " + quoted(dir.file("outside.txt")), "outside the map"},
        {quoted(officeMap()) + " --poses " + quoted(dir.file("nothere.txt")), "nothere.txt"},
        {quoted(officeMap()), "exactly one of --poses"},
        {quoted(officeMap()) + " --tour --beams 1", "beams"},
        {quoted(officeMap()) + " --tour --format xml", "format"},
        {quoted(officeMap()) + " --tour -c " + quoted(dir.file("no.ini")), "no.ini"},
        {quoted(officeMap()) + " --tour --no-such-option", "no-such-option"},
    };
    for (const Case& c : cases) {
        const auto r = runApp("toposlam-sim", c.args + " -o " + quoted(out));
        EXPECT_NE(r.exitCode, 0) << c.args;
        EXPECT_NE(r.output.find("error:"), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_FALSE(fs::exists(out)) << c.args;
        EXPECT_FALSE(fs::exists(dir.file("out_gt.txt"))) << c.args;
    }
    // Nothing else either (no temporary files left behind).
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path()))
        ++files;
    EXPECT_EQ(files, 4u) << "walls.gridmap.gz and the three pose files only";
}

TEST(ShareOffice, IsTheOfficeAndItsToursGroundTruth) {
    const std::string dir = toposlam::test::shareDir() + "/office";
    const FloorPlan plan = makeOfficeFloorPlan();
    const auto map = io::loadGridMap(dir + "/office.gridmap.gz");
    const auto png = io::loadGridMap(dir + "/office.png");
    EXPECT_EQ(map.getSizeX(), png.getSizeX());
    EXPECT_NEAR(map.getXMin(), png.getXMin(), 1e-6);

    // Labels: one id per room, the map's geometry, top row = highest y.
    const cv::Mat labels = cv::imread(dir + "/office_rooms.png", cv::IMREAD_UNCHANGED);
    ASSERT_EQ(labels.type(), CV_8UC1);
    ASSERT_EQ(labels.cols, static_cast<int>(map.getSizeX()));
    ASSERT_EQ(labels.rows, static_cast<int>(map.getSizeY()));
    const GridGeometry g = GridGeometry::of(map);
    const auto labelAt = [&](double x, double y) {
        return static_cast<int>(labels.at<std::uint8_t>(g.sizeY - 1 - g.cellY(y), g.cellX(x)));
    };
    for (const FloorRoom& room : plan.rooms()) {
        const double cx = (room.floor.xMin + room.floor.xMax) / 2;
        EXPECT_EQ(labelAt(cx, room.floor.yMin + 0.1), room.id) << room.name;
    }

    // The log: 300-600 scans of a 361-beam laser, stamps shared with the ground truth, and a
    // tour that enters every room.
    const auto records = io::LaserLogReader::readAll(dir + "/office.rawlog");
    const auto gt = io::loadTrajectory(dir + "/office_gt.txt");
    ASSERT_EQ(records.size(), gt.size());
    EXPECT_GE(records.size(), 300u);
    EXPECT_LE(records.size(), 600u);
    std::set<int> visited;
    for (std::size_t i = 0; i < gt.size(); ++i) {
        ASSERT_EQ(records[i].fileStamp, gt[i].stamp);
        EXPECT_EQ(records[i].scan->getScanSize(), 361u);
        visited.insert(labelAt(gt[i].pose.x, gt[i].pose.y));
    }
    visited.erase(0);
    EXPECT_EQ(visited.size(), plan.rooms().size());

    // Doors in the JSON.
    std::ifstream json(dir + "/office_rooms.json");
    const std::string text((std::istreambuf_iterator<char>(json)),
                           std::istreambuf_iterator<char>());
    std::size_t doors = 0;
    for (std::size_t p = 0; (p = text.find("\"jambs\"", p)) != std::string::npos; ++p)
        ++doors;
    EXPECT_EQ(doors, plan.doors().size());

    // share/ stays small.
    std::uintmax_t bytes = 0;
    for (const auto& e : fs::directory_iterator(dir))
        bytes += fs::file_size(e.path());
    EXPECT_LT(bytes, 2u * 1024 * 1024);
}

TEST(ShareOffice, IsReproducedBitForBitByMakeOffice) {
    TempDir dir;
    const auto r = runApp("toposlam-sim", "--make-office " + quoted(dir.path()) + " -q -c " +
                                              quoted(toposlam::test::configIni("sim-office.ini")));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string share = toposlam::test::shareDir() + "/office";
    std::size_t compared = 0;
    for (const auto& e : fs::directory_iterator(dir.path())) {
        const std::string name = e.path().filename().string();
        std::ifstream a(e.path(), std::ios::binary), b(share + "/" + name, std::ios::binary);
        ASSERT_TRUE(b) << "share/office/" << name << " is missing";
        std::ostringstream sa, sb;
        sa << a.rdbuf();
        sb << b.rdbuf();
        EXPECT_TRUE(sa.str() == sb.str())
            << "share/office/" << name << " differs from what toposlam-sim --make-office makes "
            << "now: regenerate share/office (share/doc/file-formats.md, \"Office floor plan\")";
        ++compared;
    }
    EXPECT_EQ(compared, 9u);
}

// --make-office writes nine files: all of them or none. One that cannot be written (a folder
// has its name) is an error before anything is made.
TEST(ShareOffice, MakeOfficeWritesEveryFileOrNone) {
    TempDir dir;
    fs::create_directories(dir.file("mo/office_tour.png"));
    const auto r = runApp("toposlam-sim", "--make-office " + quoted(dir.file("mo")) + " -q -c " +
                                              quoted(toposlam::test::configIni("sim-office.ini")));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("error: " + dir.file("mo/office_tour.png") + ": cannot write"),
              std::string::npos)
        << r.output;
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.file("mo")))
        ++entries;
    EXPECT_EQ(entries, 1u) << "only the folder that was there";
    // The same file as the -c file it reads.
    fs::remove(dir.file("mo/office_tour.png"));
    fs::copy_file(toposlam::test::configIni("sim-office.ini"), dir.file("mo/office_gt.txt"));
    const auto same = runApp("toposlam-sim", "--make-office " + quoted(dir.file("mo")) + " -q -c " +
                                                 quoted(dir.file("mo/office_gt.txt")));
    EXPECT_EQ(same.exitCode, 2) << same.output;
    EXPECT_NE(same.output.find("the same file as the input -c"), std::string::npos) << same.output;
}
