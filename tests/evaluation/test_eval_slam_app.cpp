// End-to-end tests of the toposlam-eval-slam app on small files made here.
#include "OfficeLaserRelations.h"

#include <gtest/gtest.h>
#include <mrpt/poses/CPose2D.h>

#include <toposlam/io/JsonFile.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/io/RawlogWriter.h>
#include <toposlam/io/Trajectory.h>

#include <TestSupport.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

using toposlam::test::runApp;
using toposlam::test::TempDir;

namespace {

using toposlam::test::contains;

using toposlam::test::readFile;

std::string write(const TempDir& dir, const std::string& name, const std::string& text) {
    std::ofstream(dir.file(name)) << text;
    return dir.file(name);
}

// Poses 1 m apart on a line; relations "no motion" -> translational errors 1, 2, 3 m.
struct Fixture {
    TempDir dir;
    std::string trajectory = write(dir, "slam.txt",
                                   "# timestamp x y yaw\n"
                                   "10 0 0 0\n11 1 0 0\n12 2 0 0\n13 3 0 0\n");
    std::string perfect = write(dir, "perfect.txt", "10 0 0 0\n11 0 0 0\n12 0 0 0\n13 0 0 0\n");
    std::string relations = write(dir, "line.relations",
                                  "10 11 0 0 0 0 0 0\n11 13 0 0 0 0 0 0\n10 13 0 0 0 0 0 0\n"
                                  "10 14 0 0 0 0 0 0\n");
    std::string json = dir.file("out.json");
};

}  // namespace

TEST(EvalSlamApp, HelpExplainsEveryOption) {
    const auto r = runApp("toposlam-eval-slam", "--help");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    for (const char* option :
         {"--relations", "--ground-truth", "--trajectory", "--icp-slam-path", "--rawlog",
          "--scan-stamps", "--json", "--name", "--gt-separation", "--stamp-tolerance",
          "--write-relations", "--plot", "--frame-offset", "--worst", "--mounting-from",
          "--laser-frame-of", "--mirrored-reference", "Kuemmerle"}) {
        EXPECT_TRUE(contains(r.output, option)) << option;
    }
}

TEST(EvalSlamApp, TableAndJsonWithKnownErrors) {
    Fixture f;
    const auto r = runApp("toposlam-eval-slam", f.trajectory + " --name mine --relations " +
                                                    f.relations + " --json " + f.json);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // Errors {1, 2, 3} m: 2 ± 1 m; squared {1, 4, 9}: 4.667 ± 4.041; 3 of 4 matched.
    EXPECT_TRUE(contains(r.output,
                         "| mine | 3 / 4 | 2.0000 ± 1.0000 | 0.000 ± 0.000 | "
                         "4.667 ± 4.041 |"))
        << r.output;
    const auto json = toposlam::io::loadJsonFile(f.json);
    const auto& mine = json.at("methods").at(0);
    EXPECT_EQ(mine.at("name"), "mine");
    EXPECT_EQ(mine.at("relations_matched"), 3);
    EXPECT_EQ(mine.at("relations_unmatched"), 1);
    EXPECT_EQ(mine.at("translation_m").at("count"), 3);
    EXPECT_EQ(mine.at("translation_m").at("mean"), 2.0);
    EXPECT_EQ(mine.at("translation_m").at("std"), 1.0);
    EXPECT_EQ(mine.at("translation_m").at("max"), 3.0);
    EXPECT_EQ(json.at("reference").at("relations"), 4);
    EXPECT_EQ(json.at("reference").at("repeated_relations"), 0);
    EXPECT_FALSE(contains(r.output, "repeating")) << r.output;
}

TEST(EvalSlamApp, SaysWhenTheRelationFileRepeatsALine) {
    Fixture f;
    const std::string repeated =
        write(f.dir, "repeated.relations", readFile(f.relations) + "11 13 0 0 0 0 0 0\n");
    const auto r = runApp("toposlam-eval-slam",
                          f.trajectory + " --relations " + repeated + " --json " + f.json);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(
        contains(r.output, "(5 relations, 1 repeating an earlier line, scored as published)"))
        << r.output;
    // Scored as published: the repeated 2 m error counts twice, {1, 2, 2, 3}.
    EXPECT_TRUE(contains(r.output, "| 4 / 5 | 2.0000 ± 0.8165 |")) << r.output;
    const auto json = toposlam::io::loadJsonFile(f.json);
    EXPECT_EQ(json.at("reference").at("repeated_relations"), 1);
}

TEST(EvalSlamApp, SeveralMethodsSideBySide) {
    Fixture f;
    const auto r =
        runApp("toposlam-eval-slam", "--trajectory odometry=" + f.trajectory + " --trajectory " +
                                         f.perfect + " --relations " + f.relations);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "| odometry | 3 / 4 | 2.0000 ± 1.0000 |")) << r.output;
    EXPECT_TRUE(contains(r.output, "| perfect | 3 / 4 | 0.0000 ± 0.0000 |")) << r.output;
}

TEST(EvalSlamApp, RowsOfFilesWithTheSameNameAreToldApartByTheirFolders) {
    // Two toposlam-slam outputs, each a trajectory.txt: the rows must not both read
    // "trajectory" in the table and the JSON.
    Fixture f;
    std::filesystem::create_directories(f.dir.file("run1"));
    std::filesystem::create_directories(f.dir.file("run2"));
    std::filesystem::copy_file(f.trajectory, f.dir.file("run1/trajectory.txt"));
    std::filesystem::copy_file(f.perfect, f.dir.file("run2/trajectory.txt"));
    const auto r =
        runApp("toposlam-eval-slam",
               f.dir.file("run1/trajectory.txt") + " " + f.dir.file("run2/trajectory.txt") +
                   " --trajectory mine=" + f.trajectory + " --trajectory mine=" + f.perfect +
                   " --relations " + f.relations + " --json " + f.json);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "| run1/trajectory | 3 / 4 | 2.0000 ± 1.0000 |")) << r.output;
    EXPECT_TRUE(contains(r.output, "| run2/trajectory | 3 / 4 | 0.0000 ± 0.0000 |")) << r.output;
    EXPECT_TRUE(contains(r.output, "| mine (slam) | 3 / 4 | 2.0000 ± 1.0000 |")) << r.output;
    EXPECT_TRUE(contains(r.output, "| mine (perfect) | 3 / 4 | 0.0000 ± 0.0000 |")) << r.output;
    const std::string json = readFile(f.json);
    EXPECT_TRUE(contains(json, "\"run1/trajectory\"")) << json;
    EXPECT_TRUE(contains(json, "\"run2/trajectory\"")) << json;
}

TEST(EvalSlamApp, AnOutputThatCannotBeWrittenIsAnErrorBeforeTheTables) {
    // A --json into a folder that does not exist: said before anything is scored, not after
    // every table was printed.
    Fixture f;
    const auto r = runApp("toposlam-eval-slam", f.trajectory + " --relations " + f.relations +
                                                    " --json " + f.dir.file("nodir/out.json"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_TRUE(contains(r.output, "nodir/out.json: cannot write the file")) << r.output;
    EXPECT_FALSE(contains(r.output, "| slam |")) << r.output;
    EXPECT_FALSE(std::filesystem::exists(f.dir.file("nodir")));
}

TEST(EvalSlamApp, WorstListsTheLargestErrorsInTheTableAndTheJson) {
    Fixture f;
    const auto r = runApp("toposlam-eval-slam", "--worst 2 --trajectory mine=" + f.trajectory +
                                                    " --trajectory " + f.perfect + " --relations " +
                                                    f.relations + " --json " + f.json);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // mine's worst: 10 -> 13 (3 m off; perfect: exact), then 11 -> 13 (2 m).
    EXPECT_TRUE(contains(r.output, "Worst relations of mine")) << r.output;
    EXPECT_TRUE(contains(r.output,
                         "| 10.000 | 3.00 | 0.000, 0.000 m, 0.0° | 3.000, 0.000 m, "
                         "0.0° | 3.000 / 0.00 | 0.000 m |"))
        << r.output;
    const auto json = toposlam::io::loadJsonFile(f.json);
    const auto& worst = json.at("methods").at(0).at("worst_relations");
    ASSERT_EQ(worst.size(), 2u);
    EXPECT_EQ(worst.at(0).at("relation"), 2);
    EXPECT_EQ(worst.at(1).at("translation_m"), 2.0);
    EXPECT_EQ(worst.at(1).at("estimate").at("x"), 2.0);
    // Without --worst there is no such list.
    const auto plain = runApp("toposlam-eval-slam", f.trajectory + " --relations " + f.relations);
    EXPECT_FALSE(contains(plain.output, "Worst relations")) << plain.output;
}

TEST(EvalSlamApp, FrameOffsetScoresTheFrameAheadOfThePoses) {
    // The robot turns on the spot by 90 deg. Relations made for a frame 0.1 m ahead of the
    // poses (a laser mounted ahead of the centre) see that frame swing by 0.1 * sqrt(2) m.
    TempDir dir;
    const std::string turn = write(dir, "turn.txt", "1 0 0 0\n2 0 0 1.5707963267948966\n");
    const std::string relations =
        write(dir, "ahead.relations", "1 2 -0.1 0.1 0 0 0 1.5707963267948966\n");
    const auto plain = runApp("toposlam-eval-slam", turn + " --name turn --relations " + relations);
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    EXPECT_TRUE(contains(plain.output, "| turn | 1 / 1 | 0.1414 ± 0.0000 |")) << plain.output;
    const std::string json = dir.file("ahead.json");
    const auto ahead =
        runApp("toposlam-eval-slam", turn + " --name turn --frame-offset 0.1 --json " + json +
                                         " --relations " + relations);
    ASSERT_EQ(ahead.exitCode, 0) << ahead.output;
    EXPECT_TRUE(contains(ahead.output, "| turn | 1 / 1 | 0.0000 ± 0.0000 |")) << ahead.output;
    EXPECT_EQ(toposlam::io::loadJsonFile(json).at("frame_offset_m"), 0.1);
}

TEST(EvalSlamApp, GroundTruthModeAddsAteAndWritesTheRelations) {
    Fixture f;
    // Truth: 21 poses 0.5 m apart on x; estimate: the same, rotated by 90 deg and shifted.
    std::string truth, estimate;
    for (int i = 0; i <= 20; ++i) {
        truth += std::to_string(100 + i) + " " + std::to_string(0.5 * i) + " 0 0\n";
        estimate +=
            std::to_string(100 + i) + " 5 " + std::to_string(0.5 * i) + " 1.5707963267948966\n";
    }
    const std::string gt = write(f.dir, "gt.txt", truth);
    const std::string est = write(f.dir, "est.txt", estimate);
    const std::string rel = f.dir.file("derived.relations");
    const std::string png = f.dir.file("plot.png");
    const auto r =
        runApp("toposlam-eval-slam", est + " --ground-truth " + gt + " --json " + f.json +
                                         " --write-relations " + rel + " --plot " + png);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // 10 m path, d = 1 m: 20 consecutive + 19 (1 m) + 9 (2 m) + 4 (4 m) + 1 (8 m) relations.
    EXPECT_TRUE(contains(r.output, "| est | 53 / 53 | 0.0000 ± 0.0000 | 0.000 ± 0.000 |"))
        << r.output;
    EXPECT_TRUE(contains(r.output, "ATE RMSE (m)")) << r.output;
    EXPECT_TRUE(contains(r.output, "| 0.0000 | 0.0000 |")) << r.output;
    EXPECT_TRUE(contains(r.output,
                         "| method | consecutive (20) | 1.00 m (19) | 2.00 m (9) | "
                         "4.00 m (4) | 8.00 m (1) |"))
        << r.output;
    const auto json = toposlam::io::loadJsonFile(f.json);
    const auto& scales = json.at("methods").at(0).at("by_separation");
    ASSERT_EQ(scales.size(), 5u);
    EXPECT_EQ(scales.back().at("separation_m"), 8.0);
    EXPECT_EQ(scales.back().at("relations_total"), 1);
    // Straight motion only: every relation is in the first turn bin.
    const auto& turns = json.at("methods").at(0).at("by_turn");
    ASSERT_EQ(turns.size(), 4u);
    EXPECT_EQ(turns.at(0).at("relations_total"), 53);
    EXPECT_EQ(turns.at(3).at("max_turn_deg"), 180.0);
    EXPECT_EQ(json.at("reference").at("kind"), "ground_truth");
    EXPECT_EQ(json.at("methods").at(0).at("ate").at("matched_poses"), 21);
    std::ifstream relationsOut(rel);
    std::size_t lines = 0;
    for (std::string line; std::getline(relationsOut, line);)
        ++lines;
    EXPECT_EQ(lines, 53u);
    EXPECT_EQ(readFile(png).substr(1, 3), "PNG") << "the plot is a PNG file";
}

TEST(EvalSlamApp, MirroredReferenceScoresATrajectoryOfTheLogsMirrorImage) {
    Fixture f;
    // The truth turns left along a circle of 5 m; the estimate is its mirror image, as SLAM on
    // the log's mirror image (toposlam-convert --mirror) would give it if it were exact.
    std::string truth, estimate, relations;
    const auto pose = [](int i) {
        const double a = 0.1 * i;
        return mrpt::poses::CPose2D(5 * std::sin(a), 5 * (1 - std::cos(a)), a);
    };
    for (int i = 0; i <= 20; ++i) {
        const auto p = pose(i);
        const std::string stamp = std::to_string(100 + i);
        truth += stamp + " " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " +
                 std::to_string(p.phi()) + "\n";
        estimate += stamp + " " + std::to_string(p.x()) + " " + std::to_string(-p.y()) + " " +
                    std::to_string(-p.phi()) + "\n";
        if (i > 0 && i % 5 == 0) {
            const auto m = pose(i) - pose(i - 5);
            relations += std::to_string(95 + i) + " " + stamp + " " + std::to_string(m.x()) + " " +
                         std::to_string(m.y()) + " 0 0 0 " + std::to_string(m.phi()) + "\n";
        }
    }
    const std::string gt = write(f.dir, "gt.txt", truth);
    const std::string est = write(f.dir, "est.txt", estimate);
    const std::string rel = write(f.dir, "arc.relations", relations);

    const auto mirrored =
        runApp("toposlam-eval-slam",
               est + " --ground-truth " + gt + " --mirrored-reference --json " + f.json);
    ASSERT_EQ(mirrored.exitCode, 0) << mirrored.output;
    EXPECT_TRUE(contains(mirrored.output, "(mirrored, ground-truth trajectory, 21 poses"))
        << mirrored.output;
    const auto json = toposlam::io::loadJsonFile(f.json);
    EXPECT_EQ(json.at("reference").at("mirrored"), true);
    const auto& method = json.at("methods").at(0);
    EXPECT_LT(method.at("translation_m").at("max").get<double>(), 1e-5);
    EXPECT_LT(method.at("ate").at("position_m").at("rms").get<double>(), 1e-5);

    // Against the reference as it is, the mirror image turns the wrong way.
    const auto plain =
        runApp("toposlam-eval-slam", est + " --ground-truth " + gt + " --json " + f.json);
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    const auto plainJson = toposlam::io::loadJsonFile(f.json);
    EXPECT_EQ(plainJson.at("reference").at("mirrored"), false);
    EXPECT_GT(plainJson.at("methods").at(0).at("ate").at("position_m").at("rms").get<double>(),
              0.5);

    // A relation file is mirrored alike: 4 relations of 0.5 rad turns, scored exactly.
    const auto onRelations =
        runApp("toposlam-eval-slam", est + " --relations " + rel + " --mirrored-reference");
    ASSERT_EQ(onRelations.exitCode, 0) << onRelations.output;
    EXPECT_TRUE(contains(onRelations.output, "| est | 4 / 4 | 0.0000 ± 0.0000 | 0.000 ± 0.000 |"))
        << onRelations.output;
}

TEST(EvalSlamApp, BadInputExitsNonZeroAndWritesNoJson) {
    Fixture f;
    const std::string badRelations =
        write(f.dir, "bad.relations", "10 11 0 0 0 0 0 0\n10 11 0 0 0 0\n");
    const std::string nanTrajectory = write(f.dir, "nan.txt", "10 0 0 0\n11 nan 0 0\n");
    const std::string otherLog = write(f.dir, "other.txt", "50 0 0 0\n51 1 0 0\n");
    const std::string nanLog =
        write(f.dir, "nan.clf", "FLASER 3 1.0 nan 1.0 0 0 0 0 0 0 10 host 10\n");
    const struct {
        std::string args, expected;
        int exitCode;  // 1 bad input, 2 bad usage
    } cases[] = {
        {f.trajectory + " --relations " + f.dir.file("missing.relations"), "missing.relations", 1},
        {f.trajectory + " --relations " + badRelations, "line 2", 1},
        {nanTrajectory + " --relations " + f.relations, "nan.txt", 1},
        {f.dir.file("missing.txt") + " --relations " + f.relations, "missing.txt", 1},
        // The log the mounting is checked against: missing, or not a laser log.
        {f.trajectory + " --relations " + f.relations + " --mounting-from " +
             f.dir.file("missing.clf"),
         "missing.clf", 1},
        {f.trajectory + " --relations " + f.relations + " --mounting-from " + badRelations,
         "not a CARMEN log", 1},
        // The log whose laser the poses are moved to: missing, not a laser log, or unreadable.
        {f.trajectory + " --relations " + f.relations + " --laser-frame-of " +
             f.dir.file("missing.clf"),
         "missing.clf", 1},
        {f.trajectory + " --relations " + f.relations + " --laser-frame-of " + badRelations,
         "not a CARMEN log", 1},
        {f.trajectory + " --relations " + f.relations + " --laser-frame-of " + nanLog,
         "nan.clf: line 1: reading 1 is nan", 1},
        // Nothing measured is not a result: stamps of another log match no relation.
        {otherLog + " --relations " + f.relations, "other.txt: matches none of the 4 relations", 1},
        {"--icp-slam-path " + f.trajectory + " --relations " + f.relations, "--rawlog", 2},
        {"--relations " + f.relations, "no trajectory", 2},
        {f.trajectory + " " + f.perfect + " --name x --relations " + f.relations, "--name", 2},
        {f.trajectory + " --relations " + f.relations + " --stamp-tolerance -1",
         "--stamp-tolerance", 2},
        {f.trajectory + " --relations " + f.relations + " --bogus", "--bogus", 2},
    };
    for (const auto& c : cases) {
        const auto r = runApp("toposlam-eval-slam", c.args + " --json " + f.json);
        EXPECT_EQ(r.exitCode, c.exitCode) << c.args << "\n" << r.output;
        EXPECT_TRUE(contains(r.output, "error: ")) << r.output;
        EXPECT_TRUE(contains(r.output, c.expected)) << r.output;
        EXPECT_FALSE(std::filesystem::exists(f.json)) << "no JSON after a failure: " << c.args;
    }
    // An existing JSON is left as it was when a later run fails.
    write(f.dir, "out.json", "previous");
    const auto r = runApp("toposlam-eval-slam",
                          nanTrajectory + " --relations " + f.relations + " --json " + f.json);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_EQ(readFile(f.json), "previous");
    // Neither option, or both: a usage error.
    EXPECT_EQ(runApp("toposlam-eval-slam", f.trajectory).exitCode, 2);
    EXPECT_EQ(runApp("toposlam-eval-slam", f.trajectory + " --relations " + f.relations +
                                               " --ground-truth " + f.trajectory)
                  .exitCode,
              2);
    // An option that only qualifies one that is not given would be ignored: a usage error.
    const auto lone = runApp("toposlam-eval-slam", f.trajectory + " --relations " + f.relations +
                                                       " --rawlog " + f.trajectory);
    EXPECT_EQ(lone.exitCode, 2) << lone.output;
    EXPECT_TRUE(contains(lone.output, "--rawlog stamps --icp-slam-path lines, and none is given"))
        << lone.output;
}

TEST(EvalSlamApp, OdometryOfALogAndIcpSlamPathWithTheLogsStamps) {
    TempDir dir;
    // A 3-scan CARMEN log moving 0.5 m per scan along x. Its second stamp was printed the old
    // CARMEN way, without zero padding ("101.45670" = 101.045670 s): it goes backwards, as 631
    // of intel's do. Relation files use the printed stamps.
    std::string clf;
    const char* stamps[] = {"100.900000", "101.45670", "101.100000"};
    for (int i = 0; i < 3; ++i) {
        clf += "FLASER 180";
        for (int b = 0; b < 180; ++b)
            clf += " 2.0";
        const std::string x = std::to_string(0.5 * i);
        clf += " " + x + " 0 0 " + x + " 0 0 " + stamps[i] + " nohost " + stamps[i] + "\n";
    }
    const std::string log = write(dir, "tiny.clf", clf);
    const std::string relations = write(dir, "tiny.relations",
                                        "100.9 101.4567 0.5 0 0 0 0 0\n"
                                        "101.4567 101.1 0.5 0 0 0 0 0\n");

    // The rawlog icp-slam would run on (odometry + scan per record: 6 entries), and an
    // icp-slam path with the true poses on the scan lines 1, 3, 5.
    const std::string rawlog = dir.file("tiny.rawlog");
    {
        toposlam::io::RawlogWriter writer(rawlog, toposlam::io::RawlogFormat::Observations);
        for (const auto& record : toposlam::io::LaserLogReader::readAll(log))
            writer.write(record);
        writer.commit();
    }
    const std::string path = write(dir, "log_estimated_path.txt",
                                   "0 0 0 0\n1 0 0 0\n2 0.5 0 0\n3 0.5 0 0\n4 1 0 0\n5 1 0 0\n");

    const std::string common = " --relations " + relations + " --icp-slam-path " + path +
                               " --rawlog " + rawlog + " --odometry-of " + log;
    const auto withStamps = runApp("toposlam-eval-slam", common + " --scan-stamps " + log);
    ASSERT_EQ(withStamps.exitCode, 0) << withStamps.output;
    EXPECT_TRUE(contains(withStamps.output, "| odometry | 2 / 2 | 0.0000 ± 0.0000 |"))
        << withStamps.output;
    EXPECT_TRUE(contains(withStamps.output, "| icp-slam | 2 / 2 | 0.0000 ± 0.0000 |"))
        << withStamps.output;
    // Without --scan-stamps the rawlog's stamps are used: the converter made them increasing
    // (101.045670 s), so the relations that name the printed stamp do not match: no result.
    const auto rawlogStamps = runApp("toposlam-eval-slam", common);
    EXPECT_EQ(rawlogStamps.exitCode, 1) << rawlogStamps.output;
    EXPECT_TRUE(
        contains(rawlogStamps.output, "error: " + path + ": matches none of the 2 relations"))
        << rawlogStamps.output;
}

TEST(EvalSlamApp, BundledSimulatedOfficeLogScoresAgainstItsGroundTruth) {
    // share/office: the simulator's log and its ground truth carry the same stamps, so every
    // derived relation and every pose matches; its odometry has simulated drift.
    const std::string office = toposlam::test::shareDir() + "/office/";
    ASSERT_TRUE(std::filesystem::exists(office + "office_gt.txt")) << office;
    TempDir dir;
    const auto r = runApp("toposlam-eval-slam", "--odometry-of " + office + "office.rawlog" +
                                                    " --ground-truth " + office + "office_gt.txt" +
                                                    " --json " + dir.file("office.json"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto json = toposlam::io::loadJsonFile(dir.file("office.json"));
    const auto& odometry = json.at("methods").at(0);
    EXPECT_EQ(odometry.at("relations_unmatched"), 0);
    EXPECT_EQ(odometry.at("ate").at("matched_poses"),
              json.at("reference").at("ground_truth_poses"));
    EXPECT_FALSE(contains(r.output, "| 0.0000 ± 0.0000 |")) << "odometry drift is not zero";
}

TEST(EvalSlamApp, MountingFromTheOdometryFindsWhereThePosesSitOnTheRobot) {
    // The bundled office: its ground truth gives the robot's poses, so against the log's
    // odometry they sit at the robot's origin; the same poses moved 0.2 m ahead, as a laser
    // mounted there would give them, sit 0.2 m ahead. The odometry drifts (simulated noise), so
    // both within 1 cm.
    const std::string office = toposlam::test::shareDir() + "/office/";
    TempDir dir;
    std::string ahead;
    for (const auto& p : toposlam::io::loadTrajectory(office + "office_gt.txt")) {
        ahead += std::to_string(p.stamp) + " " +
                 std::to_string(p.pose.x + 0.2 * std::cos(p.pose.phi)) + " " +
                 std::to_string(p.pose.y + 0.2 * std::sin(p.pose.phi)) + " " +
                 std::to_string(p.pose.phi) + "\n";
    }
    write(dir, "ahead.txt", ahead);
    const auto r =
        runApp("toposlam-eval-slam",
               "--ground-truth " + office + "office_gt.txt --trajectory truth=" + office +
                   "office_gt.txt --trajectory ahead=" + dir.file("ahead.txt") +
                   " --stamp-tolerance 1e-4 --mounting-from " + office + "office.rawlog --json " +
                   dir.file("m.json"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(contains(r.output, "Where each trajectory's poses sit on the robot")) << r.output;
    const auto json = toposlam::io::loadJsonFile(dir.file("m.json"));
    const auto& truth = json.at("methods").at(0).at("mounting");
    const auto& moved = json.at("methods").at(1).at("mounting");
    EXPECT_NEAR(truth.at("x").get<double>(), 0.0, 0.01) << r.output;
    EXPECT_NEAR(truth.at("y").get<double>(), 0.0, 0.01) << r.output;
    EXPECT_NEAR(moved.at("x").get<double>(), 0.2, 0.01) << r.output;
    EXPECT_NEAR(moved.at("y").get<double>(), 0.0, 0.01) << r.output;
    EXPECT_GT(moved.at("pairs").get<int>(), 20) << r.output;
}

TEST(EvalSlamApp, LaserFrameOfScoresTheLasersPosesAgainstRelationsMadeThere) {
    // The office's ground truth (the robot's poses) against relations made at its laser, 0.2 m
    // ahead: exact at the laser each scan of the log states, off on every turn without it.
    const std::string office = toposlam::test::shareDir() + "/office/";
    TempDir dir;
    const std::string relations = dir.file("laser.relations");
    toposlam::evaluation::test_paths::writeOfficeLaserRelations(relations);
    const std::string common =
        "--relations " + relations + " --trajectory robot=" + office + "office_gt.txt";
    const auto atLaser =
        runApp("toposlam-eval-slam", common + " --laser-frame-of " + office +
                                         "office.rawlog --json " + dir.file("l.json"));
    ASSERT_EQ(atLaser.exitCode, 0) << atLaser.output;
    EXPECT_TRUE(contains(atLaser.output, "Scored at the laser of each scan of " + office +
                                             "office.rawlog (typically 0.200, 0.000 m"))
        << atLaser.output;
    const auto json = toposlam::io::loadJsonFile(dir.file("l.json"));
    EXPECT_NEAR(json.at("laser_frame").at("position_m").at(0).get<double>(), 0.2, 1e-6);
    const auto& robot = json.at("methods").at(0);
    EXPECT_EQ(robot.at("relations_unmatched"), 0);
    EXPECT_LT(robot.at("translation_m").at("max").get<double>(), 1e-5);  // printed to 1e-6 m

    const auto asGiven = runApp("toposlam-eval-slam", common + " --json " + dir.file("r.json"));
    ASSERT_EQ(asGiven.exitCode, 0) << asGiven.output;
    const auto robotFrame = toposlam::io::loadJsonFile(dir.file("r.json")).at("methods").at(0);
    EXPECT_GT(robotFrame.at("translation_m").at("mean").get<double>(), 0.01) << asGiven.output;
    EXPECT_EQ(toposlam::io::loadJsonFile(dir.file("r.json")).at("laser_frame").at("log"), "");
}
