// Every app that writes files refuses, as bad usage (status 2) before any work, an output on
// one of the files it reads: its inputs, the .yaml sidecar of a map picture, a file in its
// output folder that is one of its inputs. The input is left as it was.
#include <TestSupport.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

using toposlam::test::quoted;
using toposlam::test::readFile;
using toposlam::test::runApp;
using toposlam::test::TempDir;
namespace fs = std::filesystem;

namespace {

std::string office(const std::string& file) {
    return toposlam::test::shareDir() + "/office/" + file;
}

// Runs `app args`: exit status 2, "error: " naming `written` and "the same file as the
// input", and `written` (an input) unchanged.
void expectRefused(const std::string& app, const std::string& args, const std::string& written) {
    const std::string before = readFile(written);
    ASSERT_FALSE(before.empty()) << written;
    const auto r = runApp(app, args);
    EXPECT_EQ(r.exitCode, 2) << app << " " << args << "\n" << r.output;
    EXPECT_TRUE(toposlam::test::contains(r.output, "error: ")) << r.output;
    EXPECT_TRUE(toposlam::test::contains(r.output, "the same file as the input")) << r.output;
    EXPECT_TRUE(toposlam::test::contains(r.output, fs::path(written).filename().string()))
        << r.output;
    EXPECT_EQ(readFile(written), before) << written << " was overwritten";
}

}  // namespace

TEST(OutputsOverInputs, SlamRefusesAnOutputOnItsConfigOrLog) {
    TempDir dir;
    fs::copy_file(toposlam::test::configIni("toposlam-slam.ini"), dir.file("summary.txt"));
    expectRefused("toposlam-slam",
                  quoted(dir.file("summary.txt")) + " " + quoted(office("office.rawlog")) + " -o " +
                      quoted(dir.path()),
                  dir.file("summary.txt"));
    fs::copy_file(office("office_gt.txt"), dir.file("trajectory.txt"));
    expectRefused("toposlam-slam",
                  quoted(toposlam::test::configIni("toposlam-slam.ini")) + " " +
                      quoted(dir.file("trajectory.txt")) + " -o " + quoted(dir.path()),
                  dir.file("trajectory.txt"));
}

TEST(OutputsOverInputs, RoomsRefusesAnOutputOnItsMapTrajectoryOrConfig) {
    TempDir dir;
    fs::copy_file(office("office_rooms.png"), dir.file("rooms.png"));  // a bare picture
    expectRefused("toposlam-rooms", quoted(dir.file("rooms.png")) + " -o " + quoted(dir.path()),
                  dir.file("rooms.png"));
    fs::copy_file(office("office_gt.txt"), dir.file("rooms.json"));
    expectRefused("toposlam-rooms",
                  quoted(office("office.gridmap.gz")) + " -t " + quoted(dir.file("rooms.json")) +
                      " -o " + quoted(dir.path()),
                  dir.file("rooms.json"));
    // The picture a .yaml map names is read too.
    fs::create_directory(dir.file("m"));
    fs::copy_file(office("office.png"), dir.file("m/rooms.png"));
    toposlam::test::writeText(dir.file("m/map.yaml"),
                              "image: rooms.png\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n"
                              "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
    expectRefused("toposlam-rooms", quoted(dir.file("m/map.yaml")) + " -o " + quoted(dir.file("m")),
                  dir.file("m/rooms.png"));
}

TEST(OutputsOverInputs, PlanRefusesAnOutputOnItsMapOrRooms) {
    TempDir dir;
    fs::copy_file(office("office.png"), dir.file("path.png"));
    expectRefused("toposlam-plan",
                  quoted(dir.file("path.png")) + " " + quoted(office("office_rooms.json")) +
                      " --from 1 --to 2 -o " + quoted(dir.path()),
                  dir.file("path.png"));
    fs::copy_file(office("office_rooms.json"), dir.file("path.txt"));
    expectRefused("toposlam-plan",
                  quoted(office("office.gridmap.gz")) + " " + quoted(dir.file("path.txt")) +
                      " --from 1 --to 2 -o " + quoted(dir.path()),
                  dir.file("path.txt"));
}

TEST(OutputsOverInputs, ConvertRefusesToRewriteItsInputsSidecarOrPair) {
    TempDir dir;
    for (const char* f : {"office.png", "office.yaml", "office.pgm"})
        fs::copy_file(office(f), dir.file(f));
    // The picture's sidecar, as the output itself or as the ROS pair written with a .pgm.
    expectRefused("toposlam-convert",
                  quoted(dir.file("office.png")) + " -o " + quoted(dir.file("office.yaml")) +
                      " --resolution 0.1",
                  dir.file("office.yaml"));
    expectRefused("toposlam-convert",
                  quoted(dir.file("office.png")) + " -o " + quoted(dir.file("office.pgm")),
                  dir.file("office.yaml"));
    // Without the .pgm it names, the .yaml is still read beside the picture (to tell whether
    // it is the picture's): not to be overwritten either.
    fs::create_directory(dir.file("no-pgm"));
    for (const char* f : {"office.png", "office.yaml"})
        fs::copy_file(office(f), dir.file(std::string("no-pgm/") + f));
    expectRefused("toposlam-convert",
                  quoted(dir.file("no-pgm/office.png")) + " -o " +
                      quoted(dir.file("no-pgm/office.yaml")) + " --resolution 0.1",
                  dir.file("no-pgm/office.yaml"));
    // A .yaml's picture, as the output or in the pair a .png output brings.
    expectRefused("toposlam-convert",
                  quoted(dir.file("office.yaml")) + " -o " + quoted(dir.file("office.pgm")),
                  dir.file("office.pgm"));
    expectRefused("toposlam-convert",
                  quoted(dir.file("office.yaml")) + " -o " + quoted(dir.file("office.png")),
                  dir.file("office.yaml"));
}

TEST(OutputsOverInputs, SimRefusesAnOutputOnItsMapsSidecar) {
    TempDir dir;
    for (const char* f : {"office.png", "office.yaml", "office.pgm"})
        fs::copy_file(office(f), dir.file(f));
    expectRefused("toposlam-sim",
                  quoted(dir.file("office.png")) + " --tour -q -o " + quoted(dir.file("s.rawlog")) +
                      " --gt " + quoted(dir.file("office.yaml")),
                  dir.file("office.yaml"));
    EXPECT_FALSE(fs::exists(dir.file("s.rawlog")));
}
