// TopologicalMap on disk (JSON, GraphML) and as an MRPT serializable object.
#include <toposlam/io/InputError.h>
#include <toposlam/rooms/CTopologicalMap.h>
#include <toposlam/rooms/RoomSegmenter.h>
#include <toposlam/rooms/TopologicalMapIO.h>
#include <toposlam/rooms/TopologicalMapRendering.h>

#include "DrawnMaps.h"
#include "TestSupport.h"

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include <fstream>

using namespace toposlam::rooms;

namespace {

TopologicalMap segmentedOffice() {
    static const TopologicalMap map = [] {
        TopologicalMap m = RoomSegmenter().segment(test::gridOf(test::office().image)).map;
        m.rooms[0].name = "corridor \"A\" & <co>";  // characters JSON and XML must escape
        return m;
    }();
    return map;
}

void expectSameGraph(const TopologicalMap& a, const TopologicalMap& b) {
    ASSERT_EQ(a.rooms.size(), b.rooms.size());
    for (std::size_t i = 0; i < a.rooms.size(); ++i) {
        EXPECT_EQ(a.rooms[i].id, b.rooms[i].id);
        EXPECT_EQ(a.rooms[i].name, b.rooms[i].name);
        EXPECT_DOUBLE_EQ(a.rooms[i].area, b.rooms[i].area);
        EXPECT_DOUBLE_EQ(a.rooms[i].centroid.x, b.rooms[i].centroid.x);
        EXPECT_DOUBLE_EQ(a.rooms[i].anchor.y, b.rooms[i].anchor.y);
    }
    ASSERT_EQ(a.doors.size(), b.doors.size());
    for (std::size_t i = 0; i < a.doors.size(); ++i) {
        EXPECT_EQ(a.doors[i].roomA, b.doors[i].roomA);
        EXPECT_EQ(a.doors[i].roomB, b.doors[i].roomB);
        EXPECT_DOUBLE_EQ(a.doors[i].width, b.doors[i].width);
        EXPECT_DOUBLE_EQ(a.doors[i].jambB.x, b.doors[i].jambB.x);
    }
}

// What is wrong with `text` as rooms JSON, as the InputError says it.
std::string jsonProblem(const std::string& text) {
    try {
        topologicalMapFromJson(text, "x.json");
    } catch (const toposlam::io::InputError& e) {
        EXPECT_EQ(e.file(), "x.json");
        return e.problem();
    }
    return "no error";
}

}  // namespace

TEST(TopologicalMapJson, RoundTripsEverything) {
    const TopologicalMap map = segmentedOffice();
    const toposlam::test::TempDir dir;
    saveTopologicalMap(map, dir.file("rooms.json"));
    const TopologicalMap back = loadTopologicalMap(dir.file("rooms.json"));
    expectSameGraph(map, back);
    EXPECT_EQ(back.frame.cols, map.frame.cols);
    EXPECT_DOUBLE_EQ(back.frame.resolution, map.frame.resolution);
    ASSERT_EQ(back.labels.size(), map.labels.size());
    EXPECT_EQ(cv::countNonZero(back.labels != map.labels), 0);
    EXPECT_EQ(back.rooms[2].outline.size(), map.rooms[2].outline.size());
    EXPECT_EQ(back.adjacency(), map.adjacency());
}

TEST(TopologicalMapJson, BadFilesAreInputErrorsNamingTheProblem) {
    const std::string good = topologicalMapToJson(segmentedOffice());
    EXPECT_NE(jsonProblem(good.substr(0, good.size() / 2)).find("JSON syntax error"),
              std::string::npos);
    EXPECT_NE(jsonProblem("{\"format\": \"other\"}").find("format"), std::string::npos);
    const auto at = good.find("\"labels\"");
    EXPECT_NE(
        jsonProblem(good.substr(0, at) + "\"labels\": {\"encoding\": \"runs\", \"runs\": [0, 5]}}")
            .find("cover 5 cells"),
        std::string::npos);
    EXPECT_THROW(loadTopologicalMap("/nonexistent/rooms.json"), toposlam::io::InputError);
}

TEST(TopologicalMapJson, HostileInputEndsAsAnInputError) {
    // 32 768 nested arrays: refused at a bounded depth, no stack overflow.
    EXPECT_NE(jsonProblem(std::string(32768, '[')).find("nested deeper than"), std::string::npos);
    EXPECT_NE(jsonProblem("{\"format\": \"\\uZZZZ\"}").find("JSON syntax error at line 1"),
              std::string::npos);
    EXPECT_NE(jsonProblem("{\"format\": \"toposlam-topological-map\", \"version\": 1e999}")
                  .find("number overflow"),
              std::string::npos);
}

TEST(TopologicalMapGraphML, RoundTripsGraphAndGeometry) {
    const TopologicalMap map = segmentedOffice();
    const std::string xml = topologicalMapToGraphML(map);
    EXPECT_NE(xml.find("corridor \"A\" &amp; &lt;co&gt;"), std::string::npos);
    const TopologicalMap back = topologicalMapFromGraphML(xml, "x.graphml");
    expectSameGraph(map, back);
    // The geometry rides along, so a GraphML map plans like a JSON one.
    EXPECT_EQ(back.frame.cols, map.frame.cols);
    EXPECT_EQ(back.frame.rows, map.frame.rows);
    EXPECT_DOUBLE_EQ(back.frame.resolution, map.frame.resolution);
    EXPECT_DOUBLE_EQ(back.frame.xMin, map.frame.xMin);
    ASSERT_EQ(back.labels.size(), map.labels.size());
    EXPECT_EQ(cv::countNonZero(back.labels != map.labels), 0);
    EXPECT_EQ(back.rooms[2].outline.size(), map.rooms[2].outline.size());
    EXPECT_DOUBLE_EQ(back.rooms[2].outline[1].y, map.rooms[2].outline[1].y);
}

TEST(TopologicalMapGraphML, ReadsOtherWritersGraphs) {
    // Character references beyond one byte decode to UTF-8; attributes by name, no geometry.
    const TopologicalMap m = topologicalMapFromGraphML(
        "<graphml><key id=\"n\" for=\"node\" attr.name=\"name\"/><graph>"
        "<node id=\"a\"><data key=\"n\">caf&#233; &#x4E2D;</data></node><node id=\"b\"/>"
        "<edge source=\"a\" target=\"b\"/></graph></graphml>",
        "x.graphml");
    ASSERT_EQ(m.rooms.size(), 2u);
    EXPECT_EQ(m.rooms[0].name, "caf\xC3\xA9 \xE4\xB8\xAD");
    ASSERT_EQ(m.doors.size(), 1u);
    EXPECT_EQ(m.doors[0].roomB, 2);
    EXPECT_TRUE(m.labels.empty());
    EXPECT_EQ(m.frame.cols, 0);
}

TEST(TopologicalMapGraphML, BadFilesAreInputErrors) {
    for (const char* text : {
             "<graphml><node id=\"a\"/></graphml>",  // no <graph>
             "<graphml><graph><node id=\"a\"/><edge source=\"a\" target=\"b\"/></graph>"
             "</graphml>",                                         // edge to an unknown node
             "<graphml><graph><node id=\"a\"></graph></graphml>",  // not XML
             "<graphml><key id=\"c\" for=\"graph\" attr.name=\"cols\"/><graph>"
             "<data key=\"c\">-3</data></graph></graphml>",  // bad frame
         }) {
        EXPECT_THROW(topologicalMapFromGraphML(text, "x.graphml"), toposlam::io::InputError)
            << text;
    }
}

TEST(CTopologicalMap, SerializesAndIsRegistered) {
    const CTopologicalMap original(segmentedOffice());
    mrpt::io::CMemoryStream buffer;
    mrpt::serialization::archiveFrom(buffer) << original;
    buffer.Seek(0);
    mrpt::serialization::CSerializable::Ptr object;
    mrpt::serialization::archiveFrom(buffer) >> object;  // by class name, through the registry
    const auto back = std::dynamic_pointer_cast<CTopologicalMap>(object);
    ASSERT_TRUE(back);
    expectSameGraph(original.map, back->map);
    EXPECT_EQ(cv::countNonZero(back->map.labels != original.map.labels), 0);
    EXPECT_NE(mrpt::rtti::findRegisteredClass("toposlam::rooms::CTopologicalMap"), nullptr);
    EXPECT_NE(back->asString().find("6 rooms, 6 doors"), std::string::npos) << back->asString();
}

TEST(TopologicalMapRendering, DrawsRoomsAndDoors) {
    const TopologicalMap map = segmentedOffice();
    RenderOptions options;
    options.scale = 2;
    const cv::Mat img = renderTopologicalMap(map, options);
    EXPECT_EQ(img.cols, 2 * map.frame.cols);
    EXPECT_EQ(img.type(), CV_8UC3);
    // A room's anchor region has its room colour around the written id; walls are dark.
    const cv::Point2f wall = map.frame.toPixel(1.1, 5);
    EXPECT_LT(img.at<cv::Vec3b>(cvRound(wall.y * 2), cvRound(wall.x * 2))[1], 60);
    const toposlam::test::TempDir dir;
    saveTopologicalMapPng(map, dir.file("rooms.png"), options);
    std::ifstream png(dir.file("rooms.png"), std::ios::binary);
    char magic[4] = {};
    png.read(magic, 4);
    EXPECT_EQ(std::string(magic + 1, 3), "PNG");
}
