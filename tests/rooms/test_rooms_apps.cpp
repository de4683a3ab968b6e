// toposlam-rooms and toposlam-bench-rooms as a user runs them.
#include <toposlam/io/Trajectory.h>
#include <toposlam/rooms/TopologicalMapIO.h>

#include "DrawnMaps.h"
#include "SimulatedDrive.h"
#include "TestSupport.h"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

using toposlam::test::runApp;
using toposlam::test::TempDir;

TEST(ToposlamRooms, SegmentsADrawnOfficeAndWritesEveryOutput) {
    const TempDir dir;
    const auto drawn = toposlam::rooms::test::office();
    ASSERT_TRUE(cv::imwrite(dir.file("office.png"), drawn.image));  // bare PNG: p(free) = grey/255
    const auto r =
        runApp("toposlam-rooms", "'" + dir.file("office.png") + "' -o '" + dir.file("out") + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("6 rooms, 6 doors"), std::string::npos) << r.output;
    for (const char* f :
         {"rooms.json", "rooms.graphml", "rooms.png", "rooms-steps.png", "rooms.topomap.gz"}) {
        EXPECT_TRUE(std::filesystem::is_regular_file(dir.file(std::string("out/") + f))) << f;
    }
    const auto map = toposlam::rooms::loadTopologicalMap(dir.file("out/rooms.json"));
    EXPECT_EQ(map.rooms.size(), 6u);
    EXPECT_EQ(map.doors.size(), 6u);
    EXPECT_EQ(toposlam::rooms::loadTopologicalMap(dir.file("out/rooms.graphml")).doors.size(), 6u);
}

TEST(ToposlamRooms, AnOriginOrResolutionAloneKeepsTheSidecarsOtherValues) {
    const TempDir dir;
    ASSERT_TRUE(cv::imwrite(dir.file("m.png"), toposlam::rooms::test::office().image));
    toposlam::test::writeText(dir.file("m.yaml"),
                              "image: m.png\nresolution: 0.1\norigin: [-0.7, -0.7, 0]\nnegate: "
                              "0\noccupied_thresh: 0.65\nfree_thresh: 0.196\nmode: trinary\n");
    auto r = runApp("toposlam-rooms",
                    "'" + dir.file("m.png") + "' --origin 1,2 -q -o '" + dir.file("a") + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto moved = toposlam::rooms::loadTopologicalMap(dir.file("a/rooms.json"));
    EXPECT_FLOAT_EQ(moved.frame.resolution, 0.1) << "the sidecar's, not 0.05";
    EXPECT_FLOAT_EQ(moved.frame.xMin, 1.0);
    r = runApp("toposlam-rooms",
               "'" + dir.file("m.png") + "' --resolution 0.2 -q -o '" + dir.file("b") + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto scaled = toposlam::rooms::loadTopologicalMap(dir.file("b/rooms.json"));
    EXPECT_FLOAT_EQ(scaled.frame.resolution, 0.2);
    EXPECT_FLOAT_EQ(scaled.frame.xMin, -0.7) << "the sidecar's, not 0";
}

TEST(ToposlamRooms, AFailedWriteLeavesThePreviousRunsFilesAsTheyWere) {
    const TempDir dir;
    ASSERT_TRUE(cv::imwrite(dir.file("office.png"), toposlam::rooms::test::office().image));
    const std::string args = "'" + dir.file("office.png") + "' -o '" + dir.file("out") + "'";
    ASSERT_EQ(runApp("toposlam-rooms", args).exitCode, 0);
    const std::string previousJson = toposlam::test::readFile(dir.file("out/rooms.json"));
    // The last of the five outputs cannot be written: a folder has its name.
    std::filesystem::remove(dir.file("out/rooms.topomap.gz"));
    std::filesystem::create_directory(dir.file("out/rooms.topomap.gz"));
    std::filesystem::remove(dir.file("out/rooms.png"));
    const auto r = runApp("toposlam-rooms", args + " --door-width 1.2");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("rooms.topomap.gz: cannot write the output file"), std::string::npos)
        << r.output;
    EXPECT_EQ(toposlam::test::readFile(dir.file("out/rooms.json")), previousJson);
    EXPECT_FALSE(std::filesystem::exists(dir.file("out/rooms.png"))) << "none of this run's files";
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.file("out")))
        ++files;
    EXPECT_EQ(files, 4u)
        << "the previous json, graphml, steps picture and the folder; no temporary";
}

TEST(ToposlamRooms, DrawnPlanWithGreyWallsIsReadAsDrawn) {
    // Walls drawn in mid-grey (p(free) = 0.63): read as a SLAM grid (--grid) they are unknown
    // space, far from any occupied cell, so no wall frames a door. A picture of white and mid
    // grey alone is taken for a drawn plan (no occupied cell: nothing would bound the rooms),
    // as --drawn reads it, and a note says so.
    const TempDir dir;
    const auto drawn = toposlam::rooms::test::office();
    cv::Mat grey = drawn.image.clone();
    grey.setTo(160, drawn.image == 0);
    ASSERT_TRUE(cv::imwrite(dir.file("office.png"), grey));
    for (const char* reading : {" --drawn", ""}) {
        const auto r = runApp("toposlam-rooms", "'" + dir.file("office.png") + "'" + reading +
                                                    " -o '" + dir.file("drawn") + "'");
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find("6 rooms, 6 doors"), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("read as a drawn floor plan") != std::string::npos,
                  *reading == '\0')
            << r.output;  // the note only when the reading was guessed
    }
    auto r = runApp("toposlam-rooms",
                    "'" + dir.file("office.png") + "' --grid -o '" + dir.file("grid") + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_LT(toposlam::rooms::loadTopologicalMap(dir.file("grid/rooms.json")).rooms.size(), 6u);
    r = runApp("toposlam-rooms",
               "'" + dir.file("office.png") + "' --grid --drawn -o '" + dir.file("both") + "'");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--drawn and --grid"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("both"))) << "nothing written on bad usage";
}

TEST(ToposlamRooms, PublicMapPicturesAreReadAsWhatTheyAre) {
    // Pictures of the room-segmentation benchmark's folder, given bare, as a user would. Read
    // as grids (p(free) = grey / 255, as every bare picture was before the guess), intel_map's
    // light-grey background (230) and Freiburg52_scan's light-grey walls (211) are free space
    // and each map is one room; freiburg_building101 is a SLAM map (mid-grey unknown, black
    // walls). Bormann et al.'s ground truth has 10 rooms for Freiburg52_scan.
    TOPOSLAM_SHARED_DATA_OR_SKIP(intel, "rooms/intel_map.png");
    TOPOSLAM_SHARED_DATA_OR_SKIP(freiburg52, "rooms/Freiburg52_scan.png");
    TOPOSLAM_SHARED_DATA_OR_SKIP(building101, "rooms/freiburg_building101.png");
    const TempDir dir;
    const auto rooms = [&](const std::string& map, const std::string& options) {
        const auto r = runApp("toposlam-rooms",
                              "'" + map + "' " + options + " -q -o '" + dir.file("out") + "'");
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return std::make_pair(
            toposlam::rooms::loadTopologicalMap(dir.file("out/rooms.json")).rooms.size(), r.output);
    };
    for (const std::string& map : {intel, freiburg52}) {
        const auto [guessed, note] = rooms(map, "");
        EXPECT_NE(note.find("read as a drawn floor plan"), std::string::npos) << note;
        EXPECT_GE(guessed, 8u) << map;
        EXPECT_EQ(rooms(map, "--drawn").first, guessed) << map;
        EXPECT_EQ(rooms(map, "--grid").first, 1u) << map;
    }
    const auto [guessed, note] = rooms(building101, "");
    EXPECT_NE(note.find("read as an occupancy grid"), std::string::npos) << note;
    EXPECT_EQ(rooms(building101, "--grid").first, guessed);
}

TEST(ToposlamRooms, UsesTheTrajectory) {
    const TempDir dir;
    const auto drawn = toposlam::rooms::test::office();
    ASSERT_TRUE(cv::imwrite(dir.file("office.png"), drawn.image));
    {
        std::ofstream traj(dir.file("tour.txt"));
        traj << "# timestamp x y yaw\n";
        for (std::size_t i = 0; i < drawn.tour.size(); ++i)
            traj << i << " " << drawn.tour[i].x << " " << drawn.tour[i].y << " 0\n";
    }
    const auto r =
        runApp("toposlam-rooms", "'" + dir.file("office.png") + "' -t '" + dir.file("tour.txt") +
                                     "' --paper -o '" + dir.file("out") + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("6 rooms, 6 doors (trajectory search"), std::string::npos) << r.output;
}

TEST(ToposlamRooms, OfficesMappedFromTheCorridorOnlyAreRoomsOnTheSlamGrid) {
    // A robot drives once round a ring corridor (and on along its first stretch, to close the
    // loop) and sees each office only through its door: on the SLAM grid the offices are
    // streaked with unknown cells between the beams and their corners beside the doors are
    // unknown. The streaks once made one cell the building's wall thickness, and the jambs of
    // the doors (0.2 m walls) failed the wall-end test: 1 room, no door.
    const TempDir dir;
    const auto drawn = toposlam::rooms::test::corridorRing();
    ASSERT_TRUE(cv::imwrite(dir.file("ring.png"), drawn.image));
    auto waypoints = drawn.tour;
    waypoints.push_back({20, waypoints.front().y});
    toposlam::io::Trajectory2D drive;
    for (const auto& pose : toposlam::test::drivePath(waypoints))  // 0.1 m apart, at 10 Hz
        drive.push_back({100 + 0.1 * static_cast<double>(drive.size()), pose.asTPose()});
    toposlam::io::saveTrajectory(drive, dir.file("drive.txt"));
    auto r =
        runApp("toposlam-sim", "'" + dir.file("ring.png") + "' --poses '" + dir.file("drive.txt") +
                                   "' -q -o '" + dir.file("ring.rawlog") + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runApp("toposlam-slam", "'" + toposlam::test::configIni("toposlam-slam.ini") + "' '" +
                                    dir.file("ring.rawlog") + "' -o '" + dir.file("slam") + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runApp("toposlam-rooms", "'" + dir.file("slam/map.gridmap.gz") + "' -t '" +
                                     dir.file("slam/trajectory.txt") + "' -o '" +
                                     dir.file("rooms") + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto map = toposlam::rooms::loadTopologicalMap(dir.file("rooms/rooms.json"));
    EXPECT_EQ(map.rooms.size(), drawn.rooms.size()) << r.output;
    ASSERT_EQ(map.doors.size(), drawn.doors.size()) << r.output;
    for (const auto& door : map.doors) {
        // The clear opening (1 m) plus a cell, within two cells.
        EXPECT_NEAR(door.width, 1.05, 0.1);
        EXPECT_NE(door.roomA, door.roomB);
    }
}

TEST(ToposlamRooms, BadInputGivesAClearErrorAndNoOutput) {
    const TempDir dir;
    auto r =
        runApp("toposlam-rooms", "'" + dir.file("missing.png") + "' -o '" + dir.file("out") + "'");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("error: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("missing.png"), std::string::npos) << r.output;

    ASSERT_TRUE(cv::imwrite(dir.file("black.png"), cv::Mat(40, 40, CV_8U, cv::Scalar(0))));
    r = runApp("toposlam-rooms", "'" + dir.file("black.png") + "' -o '" + dir.file("out") + "'");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("no free cell"), std::string::npos) << r.output;

    const auto drawn = toposlam::rooms::test::office();
    ASSERT_TRUE(cv::imwrite(dir.file("office.png"), drawn.image));
    {
        std::ofstream traj(dir.file("bad.txt"));
        traj << "0 1 2\n";
    }
    r = runApp("toposlam-rooms", "'" + dir.file("office.png") + "' -t '" + dir.file("bad.txt") +
                                     "' -o '" + dir.file("out") + "'");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("bad.txt"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("out/rooms.json")));

    r = runApp("toposlam-rooms",
               "'" + dir.file("office.png") + "' --door-width -1 -o '" + dir.file("out") + "'");
    EXPECT_EQ(r.exitCode, 2) << "an out-of-range option is bad usage";
    EXPECT_NE(r.output.find("error: --door-width: '-1' is not a number in (0, 10]"),
              std::string::npos)
        << r.output;
}

TEST(ToposlamBenchRooms, RunsOneMapAndWritesJson) {
    TOPOSLAM_SHARED_DATA_OR_SKIP(map, "rooms/Freiburg52_scan.png");
    const TempDir dir;
    const std::string data = std::filesystem::path(map).parent_path().string();
    const auto r = runApp("toposlam-bench-rooms",
                          "--data '" + data + "' --sets bormann --maps Freiburg52_scan -r 1 -o '" +
                              dir.file("b4.json") + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // Freiburg52: 10 ground-truth rooms; every method appears for both variants.
    for (const char* method : {"vdoor", "vdoor-paper", "morph", "dist"}) {
        EXPECT_NE(r.output.find("| bormann | Freiburg52_scan_furnitures | 0 | " +
                                std::string(method) + " |"),
                  std::string::npos)
            << method;
    }
    EXPECT_NE(r.output.find("/ 10 |"), std::string::npos) << r.output;
    EXPECT_TRUE(std::filesystem::is_regular_file(dir.file("b4.json")));
}

TEST(ToposlamBenchRooms, SkipsWithAMessageWithoutData) {
    const TempDir dir;
    const auto r =
        runApp("toposlam-bench-rooms", "--data '" + dir.file("nothing") + "' --sets bormann -o '" +
                                           dir.file("b4.json") + "'");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.output.find("B4 skipped"), std::string::npos) << r.output;
}

TEST(ToposlamBenchRooms, RunsGeneratedPlansAtTwoAnglesAndWritesThem) {
    const TempDir dir;
    auto r = runApp("toposlam-bench-rooms",
                    "--sets gen,flats --gen-seeds 1 --flat-seeds 1 -m vdoor,morph -r 1 "
                    "--rotations 0,17 -o '" +
                        dir.file("gen.json") + "'");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* row :
         {"| gen | gen01_furnitures | 17 | vdoor |", "| gen | gen01 | 0 | morph |",
          "| gen | vdoor | furnished | all |", "| flats | flat01_furnitures | 17 | vdoor |",
          "| flats | morph | unfurnished | all |"}) {
        EXPECT_NE(r.output.find(row), std::string::npos) << row << "\n" << r.output;
    }
    EXPECT_TRUE(std::filesystem::is_regular_file(dir.file("gen.json")));

    r = runApp("toposlam-bench-rooms",
               "--write-plans '" + dir.file("plans") +
                   "' --sets gen,flats,rings --gen-seeds 2 --flat-seeds 3 --ring-seeds 4 "
                   "--rotations 0,30");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* file :
         {"gen02.png", "gen02_furnitures.png", "gen02_gt_segmentation.png", "gen02_doors.json",
          "gen02_rot30_furnitures.png", "flat03.png", "flat03_rot30_gt_segmentation.png",
          "ring04_furnitures.png", "ring04_rot30_gt_segmentation.png"}) {
        EXPECT_TRUE(std::filesystem::is_regular_file(dir.file("plans/" + std::string(file))))
            << file;
    }
}

TEST(ToposlamBenchRooms, RejectsBadOptions) {
    const TempDir dir;
    // Bad usage: exit 2; a missing file: exit 1; nothing written either way.
    for (const auto& [bad, status] :
         std::vector<std::pair<std::string, int>>{{"--sets bogus", 2},
                                                  {"-r 0", 2},
                                                  {"--rotations 1e999", 2},
                                                  {"--rotations 400", 2},
                                                  {"--gen-seeds x", 2},
                                                  {"--sets flats --flat-seeds 1-x", 2},
                                                  {"--sets rings --ring-seeds x", 2},
                                                  {"--sets slam --slam-ring-seeds -3", 2},
                                                  {"--cell-size 0.07", 2},  // no whole multiple
                                                  {"--cell-size 0.03", 2},  // no whole fraction
                                                  {"-c missing.ini", 1}}) {
        const auto r = runApp("toposlam-bench-rooms", bad + " -o '" + dir.file("b.json") + "'");
        EXPECT_EQ(r.exitCode, status) << bad << "\n" << r.output;
        EXPECT_NE(r.output.find("error: "), std::string::npos) << bad << "\n" << r.output;
        EXPECT_FALSE(std::filesystem::exists(dir.file("b.json"))) << bad;
    }
}

// A door width at or below its tolerance: bad usage naming the options when the command line
// set them, bad input naming the file when a -c file did.
TEST(ToposlamRooms, ADoorWidthBelowItsToleranceNamesWhereItCameFrom) {
    const TempDir dir;
    const std::string map = toposlam::test::shareDir() + "/office/office.gridmap.gz";
    const std::string out = dir.file("out");
    const struct {
        std::string options, expected;
        int exitCode;
    } cases[] = {
        {"--door-width 0.4",
         "error: --door-width 0.4: the door width tolerance (0.5 m: --door-tolerance, or -c) must "
         "be below the door width",
         2},
        {"--door-tolerance 1.5", "error: --door-tolerance 1.5: the door width tolerance must", 2},
        {"--door-width 0.4 --door-tolerance 0.4",
         "error: --door-width 0.4, --door-tolerance 0.4: the door width tolerance must", 2},
        {"--door-tolerance 0", "error: --door-tolerance: [RoomSegmenter] door_width_tolerance", 2},
    };
    for (const auto& c : cases) {
        const auto r = runApp("toposlam-rooms", "'" + map + "' " + c.options + " -o '" + out + "'");
        EXPECT_EQ(r.exitCode, c.exitCode) << c.options << "\n" << r.output;
        EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.options << "\n" << r.output;
        EXPECT_FALSE(std::filesystem::exists(out)) << c.options;
    }
    toposlam::test::writeText(dir.file("dw.ini"), "[RoomSegmenter]\ndoor_width = 0.4\n");
    const auto r =
        runApp("toposlam-rooms", "'" + map + "' -c '" + dir.file("dw.ini") + "' -o '" + out + "'");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("error: " + dir.file("dw.ini") + ": [RoomSegmenter]"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(out));
}
