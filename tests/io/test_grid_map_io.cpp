#include <gtest/gtest.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/serialization/CArchive.h>
#include <toposlam/io/GridMapIO.h>
#include <toposlam/io/InputError.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "TestSupport.h"

namespace fs = std::filesystem;
using mrpt::maps::COccupancyGridMap2D;
using toposlam::io::GridMapGeometry;
using toposlam::io::InputError;
using toposlam::io::loadGridMap;
using toposlam::io::saveGridMap;

namespace {

// 40 x 30 cells of 0.05 m whose origin (-10.025, 3.5) is not a multiple of the resolution
// (setSize() would round it): a walled room, free inside, an unknown strip, a grey ramp.
COccupancyGridMap2D testGrid() {
    COccupancyGridMap2D g;
    g.setSize(0, 2.0f, 0, 1.5f, 0.05f, 0.5f);
    toposlam::io::setGridOrigin(g, -10.025f, 3.5f);
    for (int cy = 0; cy < 30; ++cy) {
        for (int cx = 0; cx < 40; ++cx) {
            float p = 0.95f;  // free
            if (cx == 0 || cy == 0 || cx == 39 || cy == 29)
                p = 0.05f;  // wall
            if (cx >= 30 && cx < 35)
                p = 0.5f;  // unknown
            if (cy == 15)
                p = static_cast<float>(cx) / 39.0f;  // ramp
            g.setCell(cx, cy, p);
        }
    }
    return g;
}

void expectSameGeometry(const COccupancyGridMap2D& a, const COccupancyGridMap2D& b) {
    EXPECT_EQ(a.getSizeX(), b.getSizeX());
    EXPECT_EQ(a.getSizeY(), b.getSizeY());
    EXPECT_EQ(a.getResolution(), b.getResolution());
    EXPECT_EQ(a.getXMin(), b.getXMin());  // exact (float), not rounded to the resolution
    EXPECT_EQ(a.getYMin(), b.getYMin());
    EXPECT_EQ(a.getXMax(), b.getXMax());
    EXPECT_EQ(a.getYMax(), b.getYMax());
}

// 0 occupied / 1 unknown / 2 free, with map_server's default thresholds.
int trinaryClass(float pFree) {
    const float pOcc = 1.0f - pFree;
    return pOcc > 0.65f ? 0 : pOcc < 0.196f ? 2 : 1;
}

std::string gridMapLoadError(const std::string& path,
                             const std::optional<GridMapGeometry>& geometry = std::nullopt) {
    return toposlam::test::errorOf<InputError>([&] { loadGridMap(path, geometry); });
}

using toposlam::test::writeText;

}  // namespace

TEST(GridMapIO, OriginIsKeptExactly) {
    const COccupancyGridMap2D g = testGrid();
    EXPECT_EQ(g.getXMin(), -10.025f);
    EXPECT_EQ(g.getYMin(), 3.5f);
    EXPECT_EQ(g.getSizeX(), 40u);
    EXPECT_NEAR(g.getXMax(), -10.025 + 40 * 0.05, 1e-5);
    // Cell centres follow the origin: cell 0 is centred half a cell inside it.
    EXPECT_NEAR(g.idx2x(0), -10.0, 1e-5);
    EXPECT_EQ(g.x2idx(-10.02f), 0);
}

TEST(GridMapIO, SerializedRoundTripIsExact) {
    toposlam::test::TempDir dir;
    const COccupancyGridMap2D g = testGrid();
    for (const char* name : {"m.gridmap", "m.gridmap.gz", "M.GRIDMAP.GZ"}) {
        saveGridMap(g, dir.file(name));
        const COccupancyGridMap2D back = loadGridMap(dir.file(name));
        expectSameGeometry(g, back);
        EXPECT_EQ(back.getRawMap(), g.getRawMap()) << name;
    }
    // gzip by extension: the .gz file starts with the gzip magic bytes.
    std::ifstream gz(dir.file("m.gridmap.gz"), std::ios::binary);
    EXPECT_EQ(gz.get(), 0x1f);
    EXPECT_EQ(gz.get(), 0x8b);
}

TEST(GridMapIO, PngRoundTripKeepsGeometryAndGreyLevels) {
    toposlam::test::TempDir dir;
    const COccupancyGridMap2D g = testGrid();
    saveGridMap(g, dir.file("m.png"));
    ASSERT_TRUE(fs::exists(dir.file("m.yaml"))) << "the sidecar";
    const COccupancyGridMap2D back = loadGridMap(dir.file("m.png"));
    expectSameGeometry(g, back);
    for (int cy = 0; cy < 30; ++cy) {
        for (int cx = 0; cx < 40; ++cx) {
            // 8-bit grey (1/255) plus MRPT's 8-bit log-odds cells (steps < 0.01 in p).
            EXPECT_NEAR(back.getCell(cx, cy), g.getCell(cx, cy), 0.015) << cx << "," << cy;
        }
    }
    // Image row 0 is the top (max y) row; white is free.
    const cv::Mat img = cv::imread(dir.file("m.png"), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(img.rows, 30);
    ASSERT_EQ(img.cols, 40);
    EXPECT_EQ(img.at<unsigned char>(0, 5), std::lround(g.getCell(5, 29) * 255));
    EXPECT_EQ(img.at<unsigned char>(1, 5), std::lround(g.getCell(5, 28) * 255));
    // Explicit geometry overrides the sidecar.
    const COccupancyGridMap2D moved = loadGridMap(dir.file("m.png"), GridMapGeometry{0.1, 2, 3});
    EXPECT_EQ(moved.getResolution(), 0.1f);
    EXPECT_EQ(moved.getXMin(), 2.0f);
    EXPECT_EQ(moved.getYMax(), 6.0f);
}

TEST(GridMapIO, AResolutionOrOriginAloneKeepsTheSidecarsOtherValues) {
    toposlam::test::TempDir dir;
    const COccupancyGridMap2D g = testGrid();
    saveGridMap(g, dir.file("m.png"));
    const COccupancyGridMap2D asWritten = loadGridMap(dir.file("m.png"));
    GridMapGeometry resolutionOnly;
    resolutionOnly.resolution = 0.1;
    const COccupancyGridMap2D scaled = loadGridMap(dir.file("m.png"), resolutionOnly);
    EXPECT_EQ(scaled.getResolution(), 0.1f);
    EXPECT_EQ(scaled.getXMin(), g.getXMin()) << "the sidecar's origin, not (0,0)";
    EXPECT_EQ(scaled.getYMin(), g.getYMin());
    GridMapGeometry originOnly;
    originOnly.originX = 2;
    originOnly.originY = 3;
    const COccupancyGridMap2D moved = loadGridMap(dir.file("m.png"), originOnly);
    EXPECT_EQ(moved.getResolution(), g.getResolution()) << "the sidecar's, not 0.05 m";
    EXPECT_EQ(moved.getXMin(), 2.0f);
    EXPECT_EQ(moved.getYMin(), 3.0f);
    // The greys are read as the sidecar says either way.
    for (int cy = 0; cy < 30; ++cy) {
        for (int cx = 0; cx < 40; ++cx) {
            EXPECT_EQ(scaled.getCell(cx, cy), asWritten.getCell(cx, cy)) << cx << "," << cy;
            EXPECT_EQ(moved.getCell(cx, cy), asWritten.getCell(cx, cy)) << cx << "," << cy;
        }
    }
}

TEST(GridMapIO, RosYamlPgmRoundTripIsTrinary) {
    toposlam::test::TempDir dir;
    const COccupancyGridMap2D g = testGrid();
    saveGridMap(g, dir.file("ros.yaml"));
    ASSERT_TRUE(fs::exists(dir.file("ros.pgm")));
    const COccupancyGridMap2D back = loadGridMap(dir.file("ros.yaml"));
    expectSameGeometry(g, back);
    for (int cy = 0; cy < 30; ++cy) {
        for (int cx = 0; cx < 40; ++cx) {
            EXPECT_EQ(trinaryClass(back.getCell(cx, cy)), trinaryClass(g.getCell(cx, cy)))
                << cx << "," << cy;
        }
    }
    // map_saver's grey levels: occupied 0, free 254, unknown 205.
    const cv::Mat img = cv::imread(dir.file("ros.pgm"), cv::IMREAD_UNCHANGED);
    EXPECT_EQ(img.at<unsigned char>(29, 0), 0);         // wall
    EXPECT_EQ(img.at<unsigned char>(29 - 5, 5), 254);   // free
    EXPECT_EQ(img.at<unsigned char>(29 - 5, 31), 205);  // unknown
    // Saving as .pgm writes the same pair; MRPT's own ROS loader reads it.
    saveGridMap(g, dir.file("other.pgm"));
    COccupancyGridMap2D mrptLoaded;
    ASSERT_TRUE(mrptLoaded.loadFromROSMapServerYAML(dir.file("other.yaml")));
    EXPECT_EQ(mrptLoaded.getSizeX(), 40u);
    EXPECT_EQ(mrptLoaded.getSizeY(), 30u);
}

TEST(GridMapIO, RosYamlOptionsAreHonoured) {
    toposlam::test::TempDir dir;
    // 4 x 1 image: grey 0, 100, 205, 254.
    cv::Mat img(1, 4, CV_8UC1);
    img.at<unsigned char>(0, 0) = 0;
    img.at<unsigned char>(0, 1) = 100;
    img.at<unsigned char>(0, 2) = 205;
    img.at<unsigned char>(0, 3) = 254;
    ASSERT_TRUE(cv::imwrite(dir.file("img.pgm"), img));
    const std::string common = "image: img.pgm\nresolution: 0.1\norigin: [1.5, -2.25, 0.0]\n";

    writeText(dir.file("tri.yaml"),
              common + "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
    const auto tri = loadGridMap(dir.file("tri.yaml"));
    EXPECT_EQ(tri.getXMin(), 1.5f);
    EXPECT_EQ(tri.getYMin(), -2.25f);
    EXPECT_EQ(tri.getResolution(), 0.1f);
    // p_occ = (255 - grey)/255: 1.0 occupied, 0.61 unknown, 0.196 unknown (not < 0.196), 0.004 free
    EXPECT_LT(tri.getCell(0, 0), 0.05f);
    EXPECT_NEAR(tri.getCell(1, 0), 0.5f, 0.01);
    EXPECT_NEAR(tri.getCell(2, 0), 0.5f, 0.01);
    EXPECT_GT(tri.getCell(3, 0), 0.95f);

    writeText(dir.file("neg.yaml"),
              common + "negate: 1\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
    const auto neg = loadGridMap(dir.file("neg.yaml"));
    EXPECT_GT(neg.getCell(0, 0), 0.95f);  // black is free when negated
    EXPECT_LT(neg.getCell(3, 0), 0.05f);

    writeText(dir.file("scale.yaml"),
              common + "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\nmode: scale\n");
    const auto scale = loadGridMap(dir.file("scale.yaml"));
    EXPECT_NEAR(scale.getCell(1, 0), 100 / 255.0, 0.01);

    writeText(dir.file("raw.yaml"),
              common + "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\nmode: raw\n");
    const auto raw = loadGridMap(dir.file("raw.yaml"));
    EXPECT_GT(raw.getCell(0, 0), 0.95f);         // 0 % occupied
    EXPECT_LT(raw.getCell(1, 0), 0.05f);         // 100 % occupied
    EXPECT_NEAR(raw.getCell(2, 0), 0.5f, 0.01);  // > 100: unknown
}

TEST(GridMapIO, BareImageUsesGivenGeometry) {
    toposlam::test::TempDir dir;
    cv::Mat img(20, 10, CV_8UC3, cv::Scalar(255, 255, 255));  // colour image: read as grey
    img.at<cv::Vec3b>(19, 0) = cv::Vec3b(0, 0, 0);            // bottom-left pixel black
    ASSERT_TRUE(cv::imwrite(dir.file("bare.png"), img));
    const auto defaults = loadGridMap(dir.file("bare.png"));
    EXPECT_EQ(defaults.getResolution(), 0.05f);
    EXPECT_EQ(defaults.getXMin(), 0.0f);
    EXPECT_EQ(defaults.getSizeY(), 20u);
    EXPECT_LT(defaults.getCell(0, 0), 0.05f);
    EXPECT_GT(defaults.getCell(1, 0), 0.95f);
    const auto placed = loadGridMap(dir.file("bare.png"), GridMapGeometry{0.2, -1.0, -2.0});
    EXPECT_EQ(placed.getXMax(), 1.0f);
    EXPECT_EQ(placed.getYMax(), 2.0f);
}

TEST(GridMapIO, BadInputIsReportedWithTheFileName) {
    toposlam::test::TempDir dir;
    EXPECT_NE(gridMapLoadError(dir.file("none.png")).find("none.png: file not found"),
              std::string::npos);
    EXPECT_NE(gridMapLoadError(dir.file("none.gridmap.gz")).find("file not found"),
              std::string::npos);
    EXPECT_NE(gridMapLoadError(dir.file("map.txt")).find("unknown grid map format"),
              std::string::npos);

    writeText(dir.file("junk.png"), "this is not a PNG");
    EXPECT_NE(gridMapLoadError(dir.file("junk.png")).find("junk.png: cannot read the image"),
              std::string::npos);

    writeText(dir.file("junk.gridmap"), "this is not a gridmap");
    EXPECT_NE(gridMapLoadError(dir.file("junk.gridmap")).find("not a valid .gridmap file"),
              std::string::npos);

    // A truncated .gridmap.gz: gzip data that stops early.
    saveGridMap(testGrid(), dir.file("full.gridmap.gz"));
    {
        std::ifstream in(dir.file("full.gridmap.gz"), std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), {});
        std::ofstream(dir.file("cut.gridmap.gz"), std::ios::binary)
            << bytes.substr(0, bytes.size() / 2);
    }
    EXPECT_NE(gridMapLoadError(dir.file("cut.gridmap.gz")).find("cut.gridmap.gz: "),
              std::string::npos);

    // Another MRPT class in a .gridmap file.
    {
        mrpt::io::CFileGZOutputStream out(dir.file("other.gridmap.gz"));
        mrpt::serialization::archiveFrom(out) << mrpt::poses::CPose2D(1, 2, 3);
    }
    EXPECT_NE(gridMapLoadError(dir.file("other.gridmap.gz")).find("not a valid .gridmap file"),
              std::string::npos);

    // No free cell: all occupied, or all unknown.
    COccupancyGridMap2D walls(0, 1, 0, 1, 0.1f);
    walls.fill(0.0f);
    saveGridMap(walls, dir.file("walls.gridmap"));
    EXPECT_NE(
        gridMapLoadError(dir.file("walls.gridmap")).find("walls.gridmap: map has no free cells"),
        std::string::npos);
    cv::Mat grey(5, 5, CV_8UC1, cv::Scalar(205));
    ASSERT_TRUE(cv::imwrite(dir.file("unknown.pgm"), grey));
    writeText(dir.file("unknown.yaml"),
              "image: unknown.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
              "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
    EXPECT_NE(gridMapLoadError(dir.file("unknown.yaml")).find("map has no free cells"),
              std::string::npos);

    // Bad metadata.
    writeText(dir.file("nokey.yaml"), "image: unknown.pgm\nresolution: 0.05\n");
    EXPECT_NE(gridMapLoadError(dir.file("nokey.yaml")).find("nokey.yaml: missing key 'origin'"),
              std::string::npos);
    writeText(dir.file("yaw.yaml"),
              "image: unknown.pgm\nresolution: 0.05\norigin: [0, 0, 0.5]\n"
              "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
    EXPECT_NE(gridMapLoadError(dir.file("yaw.yaml")).find("yaw"), std::string::npos);
    writeText(dir.file("noimg.yaml"),
              "image: absent.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
              "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
    EXPECT_NE(gridMapLoadError(dir.file("noimg.yaml")).find("absent.pgm: file not found"),
              std::string::npos);
    EXPECT_NE(
        gridMapLoadError(dir.file("unknown.pgm"), GridMapGeometry{0.0, 0, 0}).find("resolution"),
        std::string::npos);
    // A cell size the grid's float cannot hold (1e-300 becomes 0), an origin beyond any map.
    writeText(dir.file("tiny.yaml"),
              "image: unknown.pgm\nresolution: 1e-300\norigin: [0, 0, 0]\n"
              "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
    EXPECT_NE(gridMapLoadError(dir.file("tiny.yaml"))
                  .find("tiny.yaml: resolution 1e-300 m is out of range: a number in [0.001, 100]"),
              std::string::npos);
    writeText(dir.file("far.yaml"),
              "image: unknown.pgm\nresolution: 0.05\norigin: [1e300, 0, 0]\n"
              "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
    EXPECT_NE(
        gridMapLoadError(dir.file("far.yaml")).find("far.yaml: origin 1e+300, 0 is out of range"),
        std::string::npos);
}

TEST(GridMapIO, SaveIsAtomicAndRejectsUnknownFormats) {
    toposlam::test::TempDir dir;
    EXPECT_THROW(saveGridMap(testGrid(), dir.file("m.bmp")), std::runtime_error);
    EXPECT_THROW(saveGridMap(testGrid(), dir.file("no/such/dir/m.gridmap")), std::runtime_error);
    EXPECT_TRUE(fs::is_empty(dir.path())) << "no partial or temporary file";
}

TEST(GridMapIO, LoadsBenchmarkRoomMap) {
    TOPOSLAM_SHARED_DATA_OR_SKIP(png, "rooms/Freiburg52_scan.png");
    const auto g = loadGridMap(png, GridMapGeometry{0.05, 0, 0});
    EXPECT_EQ(g.getSizeX(), 643u);  // SOURCES.md: 643 x 354 px
    EXPECT_EQ(g.getSizeY(), 354u);
    EXPECT_NEAR(g.getXMax(), 643 * 0.05, 1e-4);
    EXPECT_GT(toposlam::io::countFreeCells(g), 10000u);
}
