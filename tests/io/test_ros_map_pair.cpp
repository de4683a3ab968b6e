// Every grid TopoSLAM writes is a ROS map_server pair that map_server loads cell for cell as
// the grid has it. The pair is read back here with map_server's documented rules
// (wiki.ros.org/map_server, "YAML format" and "Value Interpretation"), not with TopoSLAM's
// reader: the YAML's image / resolution / origin / negate / occupied_thresh / free_thresh /
// mode, an 8-bit PGM, p = (255 - x) / 255 (x / 255 with negate), p > occupied_thresh -> 100,
// p < free_thresh -> 0, otherwise -1 (mode trinary). The first image row is the top of the map.
#include <gtest/gtest.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <toposlam/io/GridMapIO.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "TestSupport.h"

namespace fs = std::filesystem;
using mrpt::maps::COccupancyGridMap2D;

namespace {

struct RosMap {
    int width = 0, height = 0;
    double resolution = 0, originX = 0, originY = 0;
    std::vector<int8_t> data;  // row-major from the bottom row (nav_msgs/OccupancyGrid)
    int at(int x, int y) const { return data[static_cast<std::size_t>(y * width + x)]; }
};

// An 8-bit binary PGM (P5): "P5 <w> <h> <maxval>" then w * h bytes, '#' comments allowed.
std::vector<uint8_t> readPgm(const std::string& path, int& width, int& height) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    in >> magic;
    EXPECT_EQ(magic, "P5") << path << " is not a binary PGM";
    const auto number = [&] {
        in >> std::ws;
        while (in.peek() == '#') {
            std::string comment;
            std::getline(in, comment);
            in >> std::ws;
        }
        int v = 0;
        in >> v;
        return v;
    };
    width = number();
    height = number();
    EXPECT_EQ(number(), 255) << "an 8-bit PGM";
    in.get();  // the single blank after maxval
    std::vector<uint8_t> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    in.read(reinterpret_cast<char*>(pixels.data()), static_cast<std::streamsize>(pixels.size()));
    EXPECT_TRUE(in.good()) << path << " is short";
    return pixels;
}

RosMap loadAsMapServer(const std::string& yamlPath) {
    const YAML::Node doc = YAML::LoadFile(yamlPath);
    EXPECT_EQ(doc["mode"].as<std::string>("trinary"), "trinary");
    const fs::path image = fs::path(yamlPath).parent_path() / doc["image"].as<std::string>();
    EXPECT_EQ(image.extension(), ".pgm");
    const bool negate = doc["negate"].as<int>() != 0;
    const double occupiedThresh = doc["occupied_thresh"].as<double>();
    const double freeThresh = doc["free_thresh"].as<double>();
    RosMap map;
    map.resolution = doc["resolution"].as<double>();
    map.originX = doc["origin"][0].as<double>();
    map.originY = doc["origin"][1].as<double>();
    const std::vector<uint8_t> pixels = readPgm(image.string(), map.width, map.height);
    map.data.resize(pixels.size());
    for (int j = 0; j < map.height; ++j) {
        for (int i = 0; i < map.width; ++i) {
            const double x = pixels[static_cast<std::size_t>(j * map.width + i)];
            const double p = negate ? x / 255.0 : (255.0 - x) / 255.0;
            const int8_t value = p > occupiedThresh ? 100 : p < freeThresh ? 0 : -1;
            map.data[static_cast<std::size_t>((map.height - 1 - j) * map.width + i)] = value;
        }
    }
    return map;
}

// What the cell is in the grid, in ROS terms with map_server's default thresholds.
int rosValue(float pFree) {
    const double pOccupied = 1.0 - pFree;
    return pOccupied > 0.65 ? 100 : pOccupied < 0.196 ? 0 : -1;
}

// Every cell of `yamlPath`'s pair, read as map_server does, equals the grid's.
void expectMapServerSeesTheGrid(const COccupancyGridMap2D& grid, const std::string& yamlPath) {
    const RosMap ros = loadAsMapServer(yamlPath);
    ASSERT_EQ(ros.width, static_cast<int>(grid.getSizeX())) << yamlPath;
    ASSERT_EQ(ros.height, static_cast<int>(grid.getSizeY())) << yamlPath;
    EXPECT_NEAR(ros.resolution, grid.getResolution(), 1e-6);
    EXPECT_NEAR(ros.originX, grid.getXMin(), 1e-5);
    EXPECT_NEAR(ros.originY, grid.getYMin(), 1e-5);
    std::size_t wrong = 0, unknown = 0;
    for (int y = 0; y < ros.height; ++y) {
        for (int x = 0; x < ros.width; ++x) {
            const int expected = rosValue(grid.getCell(x, y));
            wrong += ros.at(x, y) != expected;
            unknown += expected == -1;
        }
    }
    EXPECT_EQ(wrong, 0u) << yamlPath << ": cells map_server reads differently from the grid";
    EXPECT_GT(unknown, 0u) << "the test grid should have unknown cells";
}

// Cells of every kind, including values right at map_server's thresholds.
COccupancyGridMap2D mixedGrid() {
    COccupancyGridMap2D g;
    g.setSize(-1.0f, 1.0f, -0.5f, 0.5f, 0.05f, 0.5f);
    const float levels[] = {0.0f,  0.05f, 0.3f,   0.35f, 0.36f, 0.5f,
                            0.55f, 0.8f,  0.804f, 0.81f, 1.0f};
    int k = 0;
    for (unsigned y = 0; y < g.getSizeY(); ++y) {
        for (unsigned x = 0; x < g.getSizeX(); ++x)
            g.setCell(static_cast<int>(x), static_cast<int>(y), levels[k++ % 11]);
    }
    return g;
}

}  // namespace

TEST(RosMapPair, EveryFormatWithAnImageWritesAMapServerExactPair) {
    toposlam::test::TempDir dir;
    const COccupancyGridMap2D g = mixedGrid();
    for (const std::string name : {"a.yaml", "b.pgm", "c.png"}) {
        toposlam::io::saveGridMap(g, dir.file(name));
        const std::string yaml = fs::path(dir.file(name)).replace_extension(".yaml").string();
        ASSERT_TRUE(fs::exists(yaml)) << name;
        expectMapServerSeesTheGrid(g, yaml);
    }
    // The picture stays beside the pair for people to look at.
    EXPECT_TRUE(fs::exists(dir.file("c.png")));
    EXPECT_TRUE(fs::exists(dir.file("c.pgm")));
}

TEST(RosMapPair, ConvertWritesAMapServerExactPair) {
    toposlam::test::TempDir dir;
    const COccupancyGridMap2D g = mixedGrid();
    toposlam::io::saveGridMap(g, dir.file("in.gridmap.gz"));
    for (const std::string out : {"out.yaml", "pic.png"}) {
        const auto r = toposlam::test::runApp(
            "toposlam-convert", dir.file("in.gridmap.gz") + " -q -o " + dir.file(out));
        ASSERT_EQ(r.exitCode, 0) << r.output;
        expectMapServerSeesTheGrid(g, fs::path(dir.file(out)).replace_extension(".yaml").string());
    }
}

TEST(RosMapPair, SlamMapYamlIsAMapServerExactPair) {
    toposlam::test::TempDir dir;
    const std::string log = toposlam::test::shareDir() + "/office/office.rawlog";
    // A short stretch of the office log: the grid has free, occupied and unknown cells.
    const auto cut = toposlam::test::runApp(
        "toposlam-convert", log + " -q --max-scans 40 -o " + dir.file("short.rawlog"));
    ASSERT_EQ(cut.exitCode, 0) << cut.output;
    const auto r = toposlam::test::runApp("toposlam-slam",
                                          std::string(TOPOSLAM_CONFIG_DIR) + "/toposlam-slam.ini " +
                                              dir.file("short.rawlog") + " -o " + dir.file("out"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto grid = toposlam::io::loadGridMap(dir.file("out/map.gridmap.gz"));
    expectMapServerSeesTheGrid(grid, dir.file("out/map.yaml"));
    EXPECT_TRUE(fs::exists(dir.file("out/map.png")));
}

TEST(RosMapPair, BundledOfficeMapIsAMapServerExactPair) {
    const std::string office = toposlam::test::shareDir() + "/office/";
    const auto grid = toposlam::io::loadGridMap(office + "office.gridmap.gz");
    expectMapServerSeesTheGrid(grid, office + "office.yaml");
}
