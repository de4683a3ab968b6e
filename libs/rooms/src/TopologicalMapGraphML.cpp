#include <toposlam/io/InputError.h>
#include <toposlam/io/TextFile.h>
#include <toposlam/rooms/TopologicalMapIO.h>

#include "TopologicalMapFormat.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

namespace toposlam::rooms {

using namespace detail;

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
}  // namespace toposlam::rooms
