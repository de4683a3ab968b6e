#include <toposlam/io/InputError.h>
#include <toposlam/io/JsonFile.h>
#include <toposlam/io/TextFile.h>
#include <toposlam/rooms/TopologicalMapIO.h>

#include "TopologicalMapFormat.h"

#include <cmath>
#include <string>

namespace toposlam::rooms {

namespace {

using namespace detail;

constexpr const char* kFormat = "toposlam-topological-map";
constexpr int kVersion = 1;

// ---- JSON: typed access with messages that name the value ------------------------------------

using io::Json;

const Json& member(const Json& object, const std::string& key, const std::string& where) {
    if (!object.is_object())
        throw FormatError(where + " must be an object");
    const auto it = object.find(key);
    if (it == object.end())
        throw FormatError(where + " has no \"" + key + "\"");
    return *it;
}

double number(const Json& v, const std::string& what) {
    if (!v.is_number())
        throw FormatError(what + " must be a number");
    const double x = v.get<double>();
    if (!std::isfinite(x))
        throw FormatError(what + " must be finite");
    return x;
}

long long integer(const Json& v, const std::string& what, long long lo, long long hi) {
    const double x = v.is_number() ? v.get<double>() : NAN;
    if (!(x == std::floor(x) && x >= static_cast<double>(lo) && x <= static_cast<double>(hi))) {
        throw FormatError(what + " must be an integer in [" + std::to_string(lo) + ", " +
                          std::to_string(hi) + "]");
    }
    return v.is_number_integer() ? v.get<long long>() : static_cast<long long>(x);
}

const Json& array(const Json& v, const std::string& what) {
    if (!v.is_array())
        throw FormatError(what + " must be an array");
    return v;
}

std::string text(const Json& v, const std::string& what) {
    if (!v.is_string())
        throw FormatError(what + " must be a string");
    return v.get<std::string>();
}

mrpt::math::TPoint2D point(const Json& v, const std::string& what) {
    if (!v.is_array() || v.size() != 2)
        throw FormatError(what + " must be [x, y]");
    return {number(v[0], what + "[0]"), number(v[1], what + "[1]")};
}

Json pointJson(const mrpt::math::TPoint2D& p) {
    return Json::array({p.x, p.y});
}

Json roomJson(const Room& r) {
    Json outline = Json::array();
    for (const auto& p : r.outline)
        outline.insert(outline.end(), {p.x, p.y});
    return {{"id", r.id},
            {"name", r.name},
            {"area", r.area},
            {"centroid", pointJson(r.centroid)},
            {"anchor", pointJson(r.anchor)},
            {"outline", outline}};
}

Room roomFromJson(const Json& v, std::size_t index) {
    const std::string w = "rooms[" + std::to_string(index) + "]";
    Room r;
    r.id = static_cast<int>(integer(member(v, "id", w), w + ".id", 1, kMaxId));
    if (r.id != static_cast<int>(index) + 1)
        throw FormatError(w + ".id must be " + std::to_string(index + 1));
    if (v.contains("name"))
        r.name = text(v["name"], w + ".name");
    r.area = number(member(v, "area", w), w + ".area");
    r.centroid = point(member(v, "centroid", w), w + ".centroid");
    r.anchor = point(member(v, "anchor", w), w + ".anchor");
    const Json& outline = array(member(v, "outline", w), w + ".outline");
    if (outline.size() % 2 != 0)
        throw FormatError(w + ".outline must hold x, y pairs");
    for (std::size_t k = 0; k < outline.size(); k += 2)
        r.outline.push_back(
            {number(outline[k], w + ".outline"), number(outline[k + 1], w + ".outline")});
    return r;
}

Door doorFromJson(const Json& v, std::size_t index, int roomCount) {
    const std::string w = "doors[" + std::to_string(index) + "]";
    Door d;
    d.id = static_cast<int>(integer(member(v, "id", w), w + ".id", 1, kMaxId));
    if (d.id != static_cast<int>(index) + 1)
        throw FormatError(w + ".id must be " + std::to_string(index + 1));
    const Json& pair = array(member(v, "rooms", w), w + ".rooms");
    if (pair.size() != 2)
        throw FormatError(w + ".rooms must be [roomA, roomB]");
    d.roomA = static_cast<int>(integer(pair[0], w + ".rooms[0]", 1, roomCount));
    d.roomB = static_cast<int>(integer(pair[1], w + ".rooms[1]", 1, roomCount));
    if (d.roomA == d.roomB)
        throw FormatError(w + " joins room " + std::to_string(d.roomA) + " to itself");
    d.jambA = point(member(v, "jamb_a", w), w + ".jamb_a");
    d.jambB = point(member(v, "jamb_b", w), w + ".jamb_b");
    d.width = number(member(v, "width", w), w + ".width");
    return d;
}

GridImageFrame frameFromJson(const Json& v) {
    GridImageFrame frame;
    frame.resolution = number(member(v, "resolution", "frame"), "frame.resolution");
    frame.xMin = number(member(v, "x_min", "frame"), "frame.x_min");
    frame.yMin = number(member(v, "y_min", "frame"), "frame.y_min");
    frame.cols = static_cast<int>(integer(member(v, "cols", "frame"), "frame.cols", 0, kMaxSide));
    frame.rows = static_cast<int>(integer(member(v, "rows", "frame"), "frame.rows", 0, kMaxSide));
    checkFrame(frame);
    return frame;
}

TopologicalMap mapFromJson(const Json& doc) {
    if (text(member(doc, "format", "the document"), "format") != kFormat)
        throw FormatError(std::string("format must be \"") + kFormat + "\"");
    const long long version = integer(member(doc, "version", "the document"), "version", 1, 1000);
    if (version != kVersion) {
        throw FormatError("version " + std::to_string(version) +
                          " is not supported (this reader: " + std::to_string(kVersion) + ")");
    }
    TopologicalMap map;
    map.frame = frameFromJson(member(doc, "frame", "the document"));
    const Json& rooms = array(member(doc, "rooms", "the document"), "rooms");
    for (std::size_t i = 0; i < rooms.size(); ++i)
        map.rooms.push_back(roomFromJson(rooms[i], i));
    const int roomCount = static_cast<int>(map.rooms.size());
    const Json& doors = array(member(doc, "doors", "the document"), "doors");
    for (std::size_t i = 0; i < doors.size(); ++i)
        map.doors.push_back(doorFromJson(doors[i], i, roomCount));

    const Json& labels = member(doc, "labels", "the document");
    if (text(member(labels, "encoding", "labels"), "labels.encoding") != "runs")
        throw FormatError("labels.encoding must be \"runs\"");
    const Json& runsJson = array(member(labels, "runs", "labels"), "labels.runs");
    std::vector<long long> runs;
    runs.reserve(runsJson.size());
    for (const Json& v : runsJson)
        runs.push_back(integer(v, "labels.runs", 0, kMaxSide * kMaxSide));
    map.labels = labelsFromRuns(map.frame, runs, roomCount, "labels.runs");
    return map;
}
}  // namespace

std::string topologicalMapToJson(const TopologicalMap& map) {
    Json rooms = Json::array(), doors = Json::array(), adjacency = Json::array();
    for (const Room& r : map.rooms)
        rooms.push_back(roomJson(r));
    for (const Door& d : map.doors) {
        doors.push_back({{"id", d.id},
                         {"rooms", {d.roomA, d.roomB}},
                         {"jamb_a", pointJson(d.jambA)},
                         {"jamb_b", pointJson(d.jambB)},
                         {"width", d.width}});
    }
    for (const auto& [a, b] : map.adjacency())
        adjacency.insert(adjacency.end(), {a, b});
    const Json frame = {{"resolution", map.frame.resolution},
                        {"x_min", map.frame.xMin},
                        {"y_min", map.frame.yMin},
                        {"cols", map.frame.cols},
                        {"rows", map.frame.rows}};
    return io::formatJson({{"format", kFormat},
                           {"version", kVersion},
                           {"frame", frame},
                           {"rooms", rooms},
                           {"doors", doors},
                           {"adjacency", adjacency},
                           {"labels", {{"encoding", "runs"}, {"runs", labelRuns(map)}}}});
}

TopologicalMap topologicalMapFromJson(const std::string& text, const std::string& sourceName) {
    const Json doc = io::parseJson(text, sourceName);
    try {
        return mapFromJson(doc);
    } catch (const FormatError& e) {
        throw io::InputError(sourceName, e.what());
    }
}

void saveTopologicalMapJson(const TopologicalMap& map, const std::string& path) {
    io::saveTextFile(topologicalMapToJson(map), path);
}

TopologicalMap loadTopologicalMapJson(const std::string& path) {
    return topologicalMapFromJson(io::loadTextFile(path), path);
}
}  // namespace toposlam::rooms
