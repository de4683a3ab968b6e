#include <toposlam/io/InputError.h>
#include <toposlam/io/JsonFile.h>
#include <toposlam/io/TextFile.h>
#include <toposlam/rooms/TopologicalMapIO.h>

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>

namespace toposlam::rooms {

namespace {

constexpr const char* kFormat = "toposlam-topological-map";
constexpr int kVersion = 1;
constexpr long long kMaxSide = 1 << 20;  // cells per grid row or column
constexpr long long kMaxId = 1 << 30;

/// What is wrong inside a file; the public functions add the file name (io::InputError).
class FormatError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           std::equal(suffix.rbegin(), suffix.rend(), s.rbegin(),
                      [](char a, char b) { return std::tolower(a) == std::tolower(b); });
}

// ---- the label image as runs, shared by both formats ----------------------------------------

// Row-major runs "value, count, value, count, ..." over rows x cols cells, row 0 at the top.
std::vector<long long> labelRuns(const TopologicalMap& map) {
    std::vector<long long> runs;
    if (map.labels.empty()) {
        if (map.frame.rows > 0 && map.frame.cols > 0)  // no label image: all "no room"
            runs = {0, static_cast<long long>(map.frame.rows) * map.frame.cols};
        return runs;
    }
    int current = map.labels.at<int>(0, 0);
    long long count = 0;
    for (int r = 0; r < map.labels.rows; ++r) {
        const int* row = map.labels.ptr<int>(r);
        for (int c = 0; c < map.labels.cols; ++c) {
            if (row[c] == current) {
                ++count;
                continue;
            }
            runs.insert(runs.end(), {current, count});
            current = row[c];
            count = 1;
        }
    }
    runs.insert(runs.end(), {current, count});
    return runs;
}

cv::Mat labelsFromRuns(const GridImageFrame& frame, const std::vector<long long>& runs,
                       int roomCount, const std::string& what) {
    const long long cells = static_cast<long long>(frame.rows) * frame.cols;
    if (runs.size() % 2 != 0)
        throw FormatError(what + " must hold value, count pairs");
    if (cells == 0)
        return cv::Mat();
    cv::Mat labels(frame.rows, frame.cols, CV_32S);
    long long at = 0;
    for (std::size_t k = 0; k < runs.size(); k += 2) {
        if (runs[k] < 0 || runs[k] > roomCount) {
            throw FormatError(what + ": label " + std::to_string(runs[k]) + " is not a room (0.." +
                              std::to_string(roomCount) + ")");
        }
        if (runs[k + 1] < 1 || runs[k + 1] > cells - at)
            throw FormatError(what + " cover more than rows x cols cells");
        std::fill_n(labels.ptr<int>() + at, runs[k + 1], static_cast<int>(runs[k]));
        at += runs[k + 1];
    }
    if (at != cells) {
        throw FormatError(what + " cover " + std::to_string(at) + " cells, rows x cols is " +
                          std::to_string(cells));
    }
    return labels;
}

void checkFrame(const GridImageFrame& frame) {
    if (!(frame.resolution > 0) || !std::isfinite(frame.resolution))
        throw FormatError("frame.resolution must be > 0");
    if (!std::isfinite(frame.xMin) || !std::isfinite(frame.yMin))
        throw FormatError("frame.x_min and frame.y_min must be finite");
}

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

// ---- GraphML (tinyxml2) -----------------------------------------------------------------------

namespace {

struct GraphMLKey {
    const char* id;
    const char* domain;  // "graph", "node" or "edge"
    const char* name;    // attr.name: what readers look for
    const char* type;
};

// The map's geometry rides along as graph attributes (frame and run-length label image, same
// meaning as in JSON) and node outlines, so a GraphML file plans as well as rooms.json.
constexpr GraphMLKey kGraphMLKeys[] = {
    {"resolution", "graph", "resolution_m", "double"},
    {"x_min", "graph", "x_min_m", "double"},
    {"y_min", "graph", "y_min_m", "double"},
    {"cols", "graph", "cols", "int"},
    {"rows", "graph", "rows", "int"},
    {"label_runs", "graph", "label_runs", "string"},
    {"room_id", "node", "room_id", "int"},
    {"name", "node", "name", "string"},
    {"area", "node", "area_m2", "double"},
    {"cx", "node", "centroid_x", "double"},
    {"cy", "node", "centroid_y", "double"},
    {"ax", "node", "anchor_x", "double"},
    {"ay", "node", "anchor_y", "double"},
    {"outline", "node", "outline", "string"},
    {"door_id", "edge", "door_id", "int"},
    {"width", "edge", "width_m", "double"},
    {"jax", "edge", "jamb_a_x", "double"},
    {"jay", "edge", "jamb_a_y", "double"},
    {"jbx", "edge", "jamb_b_x", "double"},
    {"jby", "edge", "jamb_b_y", "double"},
};

// The shortest text that reads back as exactly `v` (0.05, not 0.050000000000000003).
std::string exact(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.15g", v);
    if (std::strtod(buf, nullptr) != v)
        std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}
std::string exact(long long v) {
    return std::to_string(v);
}

template <typename T>
std::string joined(const std::vector<T>& values) {
    std::string out;
    for (std::size_t i = 0; i < values.size(); ++i)
        out += (i ? " " : "") + exact(values[i]);
    return out;
}

void data(tinyxml2::XMLPrinter& xml, const char* key, const std::string& value) {
    xml.OpenElement("data");
    xml.PushAttribute("key", key);
    xml.PushText(value.c_str());
    xml.CloseElement();
}

void writeRoom(tinyxml2::XMLPrinter& xml, const Room& r) {
    xml.OpenElement("node");
    xml.PushAttribute("id", ("r" + std::to_string(r.id)).c_str());
    data(xml, "room_id", std::to_string(r.id));
    data(xml, "name", r.name);
    data(xml, "area", exact(r.area));
    data(xml, "cx", exact(r.centroid.x));
    data(xml, "cy", exact(r.centroid.y));
    data(xml, "ax", exact(r.anchor.x));
    data(xml, "ay", exact(r.anchor.y));
    std::vector<double> outline;
    for (const auto& p : r.outline)
        outline.insert(outline.end(), {p.x, p.y});
    data(xml, "outline", joined(outline));
    xml.CloseElement();
}

void writeDoor(tinyxml2::XMLPrinter& xml, const Door& d) {
    xml.OpenElement("edge");
    xml.PushAttribute("id", ("d" + std::to_string(d.id)).c_str());
    xml.PushAttribute("source", ("r" + std::to_string(d.roomA)).c_str());
    xml.PushAttribute("target", ("r" + std::to_string(d.roomB)).c_str());
    data(xml, "door_id", std::to_string(d.id));
    data(xml, "width", exact(d.width));
    data(xml, "jax", exact(d.jambA.x));
    data(xml, "jay", exact(d.jambA.y));
    data(xml, "jbx", exact(d.jambB.x));
    data(xml, "jby", exact(d.jambB.y));
    xml.CloseElement();
}

}  // namespace

std::string topologicalMapToGraphML(const TopologicalMap& map) {
    tinyxml2::XMLPrinter xml;
    xml.PushDeclaration("xml version=\"1.0\" encoding=\"UTF-8\"");
    xml.OpenElement("graphml");
    xml.PushAttribute("xmlns", "http://graphml.graphdrawing.org/xmlns");
    xml.PushAttribute("xmlns:xsi", "http://www.w3.org/2001/XMLSchema-instance");
    xml.PushAttribute("xsi:schemaLocation",
                      "http://graphml.graphdrawing.org/xmlns "
                      "http://graphml.graphdrawing.org/xmlns/1.0/graphml.xsd");
    for (const GraphMLKey& k : kGraphMLKeys) {
        xml.OpenElement("key");
        xml.PushAttribute("id", k.id);
        xml.PushAttribute("for", k.domain);
        xml.PushAttribute("attr.name", k.name);
        xml.PushAttribute("attr.type", k.type);
        xml.CloseElement();
    }
    xml.OpenElement("graph");
    xml.PushAttribute("id", "rooms");
    xml.PushAttribute("edgedefault", "undirected");
    data(xml, "resolution", exact(map.frame.resolution));
    data(xml, "x_min", exact(map.frame.xMin));
    data(xml, "y_min", exact(map.frame.yMin));
    data(xml, "cols", std::to_string(map.frame.cols));
    data(xml, "rows", std::to_string(map.frame.rows));
    data(xml, "label_runs", joined(labelRuns(map)));
    for (const Room& r : map.rooms)
        writeRoom(xml, r);
    for (const Door& d : map.doors)
        writeDoor(xml, d);
    xml.CloseElement();  // graph
    xml.CloseElement();  // graphml
    return xml.CStr();
}

namespace {

// The <data> of one element, by attribute name (attr.name of its <key>, else the key id).
class GraphMLData {
  public:
    GraphMLData(const tinyxml2::XMLElement& element,
                const std::map<std::string, std::string>& keyNames) {
        for (auto* d = element.FirstChildElement("data"); d; d = d->NextSiblingElement("data")) {
            const char* key = d->Attribute("key");
            if (!key)
                throw FormatError("<data> without key on line " + std::to_string(d->GetLineNum()));
            const auto name = keyNames.find(key);
            values_[name == keyNames.end() ? key : name->second] = d->GetText() ? d->GetText() : "";
        }
    }
    bool has(const std::string& name) const { return values_.count(name) > 0; }
    std::string text(const std::string& name) const {
        const auto it = values_.find(name);
        return it == values_.end() ? std::string() : it->second;
    }
    /// All numbers of a blank-separated list (empty when absent).
    std::vector<double> numbers(const std::string& name) const {
        std::vector<double> out;
        const std::string s = text(name);
        const char* p = s.c_str();
        for (;;) {
            while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r')
                ++p;
            if (*p == '\0')
                return out;
            char* end = nullptr;
            errno = 0;
            const double v = std::strtod(p, &end);
            if (end == p || errno == ERANGE || !std::isfinite(v) ||
                (*end != '\0' && !std::isspace(static_cast<unsigned char>(*end))))
                throw FormatError("'" + s.substr(0, 40) + "' is not a list of numbers (" + name +
                                  ")");
            out.push_back(v);
            p = end;
        }
    }
    /// One number; `fallback` when absent (graphs from other writers may leave some out).
    double real(const std::string& name, double fallback = 0) const {
        if (!has(name))
            return fallback;
        const auto v = numbers(name);
        if (v.size() != 1)
            throw FormatError("'" + text(name) + "' is not a number (" + name + ")");
        return v[0];
    }

  private:
    std::map<std::string, std::string> values_;
};

std::vector<long long> integers(const std::vector<double>& values, const std::string& what) {
    std::vector<long long> out;
    out.reserve(values.size());
    for (const double v : values) {
        if (v != std::floor(v) || std::abs(v) > static_cast<double>(kMaxSide * kMaxSide))
            throw FormatError(what + " must hold integers");
        out.push_back(static_cast<long long>(v));
    }
    return out;
}

// The frame and label image, when the file has them (TopoSLAM's writer does).
void readGeometry(const GraphMLData& graph, TopologicalMap& map) {
    if (!graph.has("cols") && !graph.has("rows"))
        return;
    map.frame.resolution = graph.real("resolution_m", NAN);
    map.frame.xMin = graph.real("x_min_m", NAN);
    map.frame.yMin = graph.real("y_min_m", NAN);
    const double cols = graph.real("cols", -1), rows = graph.real("rows", -1);
    if (!(cols >= 0 && cols <= kMaxSide && rows >= 0 && rows <= kMaxSide) ||
        cols != std::floor(cols) || rows != std::floor(rows))
        throw FormatError("graph cols and rows must be integers in [0, " +
                          std::to_string(kMaxSide) + "]");
    map.frame.cols = static_cast<int>(cols);
    map.frame.rows = static_cast<int>(rows);
    checkFrame(map.frame);
    if (graph.has("label_runs")) {
        map.labels = labelsFromRuns(map.frame, integers(graph.numbers("label_runs"), "label_runs"),
                                    static_cast<int>(map.rooms.size()), "label_runs");
    }
}

Room roomFromGraphML(const GraphMLData& n, int id) {
    Room r;
    r.id = id;
    r.name = n.text("name");
    r.area = n.real("area_m2");
    r.centroid = {n.real("centroid_x"), n.real("centroid_y")};
    r.anchor = {n.real("anchor_x"), n.real("anchor_y")};
    const auto outline = n.numbers("outline");
    if (outline.size() % 2 != 0)
        throw FormatError("outline of room " + std::to_string(id) + " must hold x, y pairs");
    for (std::size_t k = 0; k < outline.size(); k += 2)
        r.outline.push_back({outline[k], outline[k + 1]});
    return r;
}

TopologicalMap mapFromGraphML(const tinyxml2::XMLDocument& doc) {
    const tinyxml2::XMLElement* root = doc.RootElement();
    const tinyxml2::XMLElement* graph = root ? root->FirstChildElement("graph") : nullptr;
    if (!graph)
        throw FormatError("no <graph> element: not a GraphML file");
    std::map<std::string, std::string> keyNames;  // key id -> attr.name
    for (auto* k = root->FirstChildElement("key"); k; k = k->NextSiblingElement("key")) {
        if (const char* id = k->Attribute("id"))
            keyNames[id] = k->Attribute("attr.name") ? k->Attribute("attr.name") : id;
    }
    TopologicalMap map;
    std::map<std::string, int> roomOfNode;
    for (auto* n = graph->FirstChildElement("node"); n; n = n->NextSiblingElement("node")) {
        const std::string id = n->Attribute("id") ? n->Attribute("id") : "";
        const int roomId = static_cast<int>(map.rooms.size()) + 1;
        if (!roomOfNode.emplace(id, roomId).second)
            throw FormatError("duplicate node id '" + id + "'");
        map.rooms.push_back(roomFromGraphML(GraphMLData(*n, keyNames), roomId));
    }
    for (auto* e = graph->FirstChildElement("edge"); e; e = e->NextSiblingElement("edge")) {
        const std::string id = e->Attribute("id") ? e->Attribute("id") : "";
        const auto a = roomOfNode.find(e->Attribute("source") ? e->Attribute("source") : "");
        const auto b = roomOfNode.find(e->Attribute("target") ? e->Attribute("target") : "");
        if (a == roomOfNode.end() || b == roomOfNode.end())
            throw FormatError("edge '" + id + "' joins unknown nodes");
        if (a->second == b->second)
            throw FormatError("edge '" + id + "' is a loop");
        const GraphMLData data(*e, keyNames);
        Door d;
        d.id = static_cast<int>(map.doors.size()) + 1;
        d.roomA = std::min(a->second, b->second);
        d.roomB = std::max(a->second, b->second);
        d.width = data.real("width_m");
        d.jambA = {data.real("jamb_a_x"), data.real("jamb_a_y")};
        d.jambB = {data.real("jamb_b_x"), data.real("jamb_b_y")};
        map.doors.push_back(d);
    }
    readGeometry(GraphMLData(*graph, keyNames), map);
    return map;
}

}  // namespace

TopologicalMap topologicalMapFromGraphML(const std::string& text, const std::string& sourceName) {
    tinyxml2::XMLDocument doc;
    if (doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
        throw io::InputError(sourceName, std::string("GraphML: XML error on line ") +
                                             std::to_string(doc.ErrorLineNum()) + ": " +
                                             doc.ErrorName());
    }
    try {
        return mapFromGraphML(doc);
    } catch (const FormatError& e) {
        throw io::InputError(sourceName, std::string("GraphML: ") + e.what());
    }
}

void saveTopologicalMapGraphML(const TopologicalMap& map, const std::string& path) {
    io::saveTextFile(topologicalMapToGraphML(map), path);
}

TopologicalMap loadTopologicalMapGraphML(const std::string& path) {
    return topologicalMapFromGraphML(io::loadTextFile(path), path);
}

void saveTopologicalMap(const TopologicalMap& map, const std::string& path) {
    if (endsWith(path, ".json"))
        return saveTopologicalMapJson(map, path);
    if (endsWith(path, ".graphml"))
        return saveTopologicalMapGraphML(map, path);
    throw std::invalid_argument(path + ": unknown topological-map format (use .json or .graphml)");
}

TopologicalMap loadTopologicalMap(const std::string& path) {
    if (endsWith(path, ".json"))
        return loadTopologicalMapJson(path);
    if (endsWith(path, ".graphml"))
        return loadTopologicalMapGraphML(path);
    throw io::InputError(path, "unknown topological-map format (use .json or .graphml)");
}

}  // namespace toposlam::rooms
