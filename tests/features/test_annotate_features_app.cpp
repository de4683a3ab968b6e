// toposlam-annotate-features end to end, and MRPT's own rawlog-edit reading its output through
// the TopoSLAM plugin (and truncating it without: the check that this test can fail).
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/features/CObservationLaserFeatures.h>
#include <toposlam/io/RawlogWriter.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "FeatureTestScenes.h"
#include "TestSupport.h"

using namespace toposlam;

namespace {

constexpr int kScans = 6;

/// A small observations-format rawlog: odometry + a simulated scan, kScans times.
std::string writeInputLog(const test::TempDir& dir) {
    const std::string path = dir.file("in.rawlog");
    io::RawlogWriter writer(path, io::RawlogFormat::Observations);
    const auto scene = test::roomWithBox();
    for (int i = 0; i < kScans; ++i) {
        const mrpt::poses::CPose2D pose(-1 + 0.3 * i, 0.2 * i, 0.1 * i);
        io::LaserLogRecord record;
        record.index = static_cast<std::size_t>(i);
        record.scan = mrpt::obs::CObservation2DRangeScan::Create(
            test::scanOf(scene, pose, 361, M_PI, 0.01, i + 1));
        record.scan->sensorLabel = "LASER";
        record.scan->timestamp = mrpt::Clock::fromDouble(1000.0 + i);
        record.odometry = pose;
        record.hasOdometry = true;
        writer.write(record);
    }
    writer.commit();
    return path;
}

/// "Overall number of objects : N" from rawlog-edit --info, or -1.
int objectCount(const std::string& infoOutput) {
    std::smatch m;
    static const std::regex re("Overall number of objects\\s*:\\s*([0-9]+)");
    return std::regex_search(infoOutput, m, re) ? std::stoi(m[1]) : -1;
}

using toposlam::test::pluginPath;

}  // namespace

TEST(AnnotateFeaturesApp, RawlogEditReadsEveryObjectWithThePluginOnly) {
    if (test::runCommand("command -v rawlog-edit").exitCode != 0) {
        GTEST_SKIP() << "rawlog-edit (mrpt-apps) not installed";
    }
#ifdef TOPOSLAM_SANITIZED_BUILD
    GTEST_SKIP() << "the plugin is built with AddressSanitizer and MRPT's rawlog-edit is not, "
                    "so it cannot load it; the Release suite runs this test";
#endif
    test::TempDir dir;
    const std::string in = writeInputLog(dir), out = dir.file("out.rawlog");
    const auto run = test::runApp("toposlam-annotate-features",
                                  "'" + in + "' -o '" + out + "' --bearing-range -q");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    ASSERT_TRUE(std::filesystem::exists(out));

    // odometry + scan + features + corners per scan.
    const auto with =
        test::runCommand("rawlog-edit -p '" + pluginPath() + "' -i '" + out + "' --info");
    EXPECT_EQ(objectCount(with.output), 4 * kScans) << with.output;
    EXPECT_NE(with.output.find("LASER_FEATURES"), std::string::npos) << with.output;
    EXPECT_NE(with.output.find("LASER_CORNERS"), std::string::npos) << with.output;

    // Without the plugin MRPT stops at the first unknown object, quietly, exit code 0.
    const auto without = test::runCommand("rawlog-edit -i '" + out + "' --info");
    EXPECT_LT(objectCount(without.output), 4 * kScans) << without.output;
    EXPECT_NE(without.output.find("not registered"), std::string::npos) << without.output;

    // The description MRPT's tools show for our class.
    const auto describe =
        test::runCommand("rawlog-edit -p '" + pluginPath() + "' -i '" + out + "' --describe");
    EXPECT_NE(describe.output.find("TopoSLAM laser features, extracted by 'corners'"),
              std::string::npos);
}

TEST(AnnotateFeaturesApp, EveryExtractorAndOptionsFromAnIniFile) {
    test::TempDir dir;
    const std::string in = writeInputLog(dir);
    for (const char* e : {"corners", "corners-ls", "corners-paper", "segments", "split-merge"}) {
        const std::string out = dir.file(std::string(e) + ".rawlog.gz");
        const auto run =
            test::runApp("toposlam-annotate-features", "'" + in + "' -o '" + out + "' -e " + e);
        EXPECT_EQ(run.exitCode, 0) << e << ": " << run.output;
        EXPECT_NE(run.output.find("6 scans"), std::string::npos) << run.output;
        EXPECT_TRUE(std::filesystem::exists(out)) << e;
    }
    const std::string ini = dir.file("f.ini");
    {
        std::ofstream f(ini);
        f << "[CornerExtractor]\ndk_th = 2.5\nline_fit = least_squares\n";
    }
    const auto printed = test::runApp("toposlam-annotate-features",
                                      "'" + in + "' -o x.rawlog -c '" + ini + "' --print-options");
    EXPECT_EQ(printed.exitCode, 0) << printed.output;
    EXPECT_NE(printed.output.find("\ndk_th = 2.5\n"), std::string::npos) << printed.output;
    EXPECT_NE(printed.output.find("\nline_fit = least_squares\n"), std::string::npos)
        << printed.output;

    // A section that is not in the file, --section without a file, a misspelled key.
    const std::string out = dir.file("out.rawlog");
    const auto error = [&](const std::string& args) {
        const auto r =
            test::runApp("toposlam-annotate-features", "'" + in + "' -o '" + out + "' " + args);
        EXPECT_EQ(r.exitCode, 1) << args << ": " << r.output;
        EXPECT_FALSE(std::filesystem::exists(out)) << args;
        return r.output;
    };
    EXPECT_NE(error("-c '" + ini + "' -e segments")
                  .find("error: " + ini +
                        ": [SegmentExtractor]: no such section in the file; did "
                        "you mean [CornerExtractor]?"),
              std::string::npos);
    EXPECT_NE(error("-c '" + ini + "' --section Corners").find("[Corners]: no such section"),
              std::string::npos);
    const auto usage = test::runApp("toposlam-annotate-features",
                                    "'" + in + "' -o '" + out + "' --section CornerExtractor");
    EXPECT_EQ(usage.exitCode, 2) << usage.output;  // bad usage
    EXPECT_NE(usage.output.find("error: --section: no -c file"), std::string::npos);
    std::ofstream(ini) << "[CornerExtractor]\ndk_threshold = 2.5\n";
    EXPECT_NE(error("-c '" + ini + "'")
                  .find("error: " + ini +
                        ": [CornerExtractor] dk_threshold = 2.5: unknown key; "
                        "did you mean 'dk_th'?"),
              std::string::npos);
}

TEST(AnnotateFeaturesApp, BadInputIsAnErrorAndLeavesNoOutput) {
    test::TempDir dir;
    const std::string out = dir.file("out.rawlog");
    auto run = test::runApp("toposlam-annotate-features",
                            "'" + dir.file("missing.clf") + "' -o '" + out + "'");
    EXPECT_NE(run.exitCode, 0);
    EXPECT_NE(run.output.find("error:"), std::string::npos) << run.output;
    EXPECT_FALSE(std::filesystem::exists(out));
    {
        std::ofstream bad(dir.file("bad.clf"));
        bad << "FLASER 3 1.0 2.0\n";
    }
    run = test::runApp("toposlam-annotate-features",
                       "'" + dir.file("bad.clf") + "' -o '" + out + "'");
    EXPECT_NE(run.exitCode, 0) << run.output;
    EXPECT_FALSE(std::filesystem::exists(out));
    run = test::runApp("toposlam-annotate-features", "x -o y -e nonsense");
    EXPECT_NE(run.exitCode, 0);
    // A label the log does not have: the message names the labels it has.
    run = test::runApp(
        "toposlam-annotate-features",
        "'" + test::shareDir() + "/office/office.rawlog' --label NOPE -o '" + out + "'");
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("office.rawlog: no laser scans labelled 'NOPE' in the log (it has "
                              "LASER: "),
              std::string::npos)
        << run.output;
    EXPECT_FALSE(std::filesystem::exists(out));
}

// --format sf: what kf-slam and rbpf-slam read. Every entry is an (actions, sensory frame)
// pair; the action holds the odometry increment (composing them gives back the odometry of
// the input, relative to the first scan) and the frame the scan, its features and its
// corners (always, even none).
TEST(AnnotateFeaturesApp, SensoryFramesFormatForKfSlam) {
    test::TempDir dir;
    const std::string in = writeInputLog(dir), out = dir.file("sf.rawlog");
    const auto run = test::runApp("toposlam-annotate-features",
                                  "'" + in + "' -o '" + out + "' --format sf -e corners");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("sf format, 12 objects"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("corner noise"), std::string::npos) << run.output;

    mrpt::io::CFileGZInputStream file(out);
    auto archive = mrpt::serialization::archiveFrom(file);
    mrpt::obs::CActionCollection::Ptr actions;
    mrpt::obs::CSensoryFrame::Ptr frame;
    size_t entry = 0;
    int frames = 0;
    mrpt::poses::CPose2D odometry;
    while (mrpt::obs::CRawlog::readActionObservationPair(archive, actions, frame, entry)) {
        const auto move = actions->getBestMovementEstimation();
        ASSERT_TRUE(move) << "frame " << frames;
        odometry = odometry + move->poseChange->getMeanVal();
        const auto scan = frame->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
        const auto f = frame->getObservationByClass<features::CObservationLaserFeatures>();
        const auto corners = frame->getObservationByClass<mrpt::obs::CObservationBearingRange>();
        ASSERT_TRUE(scan && f && corners) << "frame " << frames;
        EXPECT_EQ(f->sensorLabel, "LASER_FEATURES");
        EXPECT_EQ(corners->sensorLabel, "LASER_CORNERS");
        EXPECT_EQ(corners->sensedData.size(), f->features.corners.size());
        EXPECT_EQ(f->timestamp, scan->timestamp);
        // The input's odometry is pose i = (-1 + 0.3 i, 0.2 i, 0.1 i); relative to pose 0:
        const mrpt::poses::CPose2D expected =
            mrpt::poses::CPose2D(-1 + 0.3 * frames, 0.2 * frames, 0.1 * frames) -
            mrpt::poses::CPose2D(-1, 0, 0);
        EXPECT_NEAR((odometry - expected).norm(), 0.0, 1e-6) << "frame " << frames;
        ++frames;
    }
    EXPECT_EQ(frames, kScans);
}

// Bad values of the new options: exit status 2, a message naming the option, no output.
TEST(AnnotateFeaturesApp, BadFormatOrOdometryNoiseIsAUsageError) {
    test::TempDir dir;
    const std::string in = writeInputLog(dir), out = dir.file("out.rawlog");
    for (const std::string args :
         {"--format xyz", "--format ''", "--odometry-noise -0.1,0.001,1,0.05,0.01,0.2",
          "--odometry-noise 0.01,0.001,1,0.05,0,0.2", "--odometry-noise nan,0.001,1,0.05,0.01,0.2",
          "--odometry-noise 1e300,0.001,1,0.05,0.01,0.2", "--odometry-noise a,b,c,d,e,f",
          "--odometry-noise 0.01,0.001",
          "--format sf --odometry-noise 0.01,0.001,1,0.05,0.01,inf"}) {
        const auto run =
            test::runApp("toposlam-annotate-features", "'" + in + "' -o '" + out + "' " + args);
        EXPECT_EQ(run.exitCode, 2) << args << ": " << run.output;
        const std::string option =
            args.find("noise") != std::string::npos ? "--odometry-noise" : "--format";
        EXPECT_NE(run.output.find("error: " + option), std::string::npos)
            << args << ": " << run.output;
        EXPECT_FALSE(std::filesystem::exists(out)) << args;
    }
}

// --feature-map writes four files beside the rawlog: all of them or none, and a place they
// cannot go is an error before the log is read.
TEST(AnnotateFeaturesApp, TheRawlogAndTheFeatureMapAreWrittenAllOrNone) {
    test::TempDir dir;
    const std::string log = writeInputLog(dir);
    {
        std::ofstream poses(dir.file("poses.txt"));
        for (int i = 0; i < kScans; ++i)
            poses << 1000 + i << " " << -1 + 0.3 * i << " " << 0.2 * i << " " << 0.1 * i << "\n";
    }
    const std::string out = dir.file("af.rawlog");
    const auto run = [&](const std::string& prefix) {
        return test::runApp("toposlam-annotate-features",
                            "'" + log + "' -o '" + out + "' --poses '" + dir.file("poses.txt") +
                                "' --feature-map '" + prefix + "'");
    };
    // No such folder.
    auto r = run(dir.file("nodir/fm"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("error: " + dir.file("nodir/fm")), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("wrote"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(out));
    // One of the four is a folder.
    std::filesystem::create_directories(dir.file("fm2/o_corners.txt"));
    r = run(dir.file("fm2/o"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("error: " + dir.file("fm2/o_corners.txt") + ": cannot write"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(out));
    for (const char* f : {"fm2/o.png", "fm2/o_segments.txt", "fm2/o_endpoints.txt"})
        EXPECT_FALSE(std::filesystem::exists(dir.file(f))) << f;
    // All five.
    r = run(dir.file("fm2/p"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(std::filesystem::is_regular_file(out));
    for (const char* f :
         {"fm2/p.png", "fm2/p_segments.txt", "fm2/p_corners.txt", "fm2/p_endpoints.txt"})
        EXPECT_TRUE(std::filesystem::is_regular_file(dir.file(f))) << f;
}
