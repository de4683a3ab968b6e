#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/InputError.h>
#include <toposlam/rooms/TopologicalMapIO.h>

#include "JsonReader.h"
#include "JsonWriter.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace toposlam::rooms {

namespace {

constexpr const char* kFormat = "toposlam-topological-map";
constexpr int kVersion = 1;

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw io::InputError(path, "cannot open the file");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad())
        throw io::InputError(path, "read error");
    return text.str();
}

void writeText(const std::string& path, const std::string& text) {
    io::writeFileAtomically(path, [&](const std::string& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        out.close();
        if (!out)
            throw std::runtime_error(path + ": cannot write the file");
    });
}

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           std::equal(suffix.rbegin(), suffix.rend(), s.rbegin(),
                      [](char a, char b) { return std::tolower(a) == std::tolower(b); });
}

void point(detail::JsonWriter& j, const std::string& key, const mrpt::math::TPoint2D& p) {
    j.key(key).beginInlineArray().value(p.x).value(p.y).endArray();
}

mrpt::math::TPoint2D readPoint(const detail::JsonValue& v, const std::string& what) {
    const auto& a = v.array(what);
    if (a.size() != 2)
        throw detail::JsonError(what + " must be [x, y]");
    return {a[0].number(what + "[0]"), a[1].number(what + "[1]")};
}

}  // namespace

std::string topologicalMapToJson(const TopologicalMap& map) {
    detail::JsonWriter j;
    j.beginObject();
    j.field("format", kFormat).field("version", kVersion);
    j.key("frame").beginObject();
    j.field("resolution", map.frame.resolution).field("x_min", map.frame.xMin);
    j.field("y_min", map.frame.yMin).field("cols", map.frame.cols).field("rows", map.frame.rows);
    j.endObject();
    j.key("rooms").beginArray();
    for (const Room& r : map.rooms) {
        j.beginObject();
        j.field("id", r.id).field("name", r.name).field("area", r.area);
        point(j, "centroid", r.centroid);
        point(j, "anchor", r.anchor);
        j.key("outline").beginInlineArray();
        for (const auto& p : r.outline)
            j.value(p.x).value(p.y);
        j.endArray();
        j.endObject();
    }
    j.endArray();
    j.key("doors").beginArray();
    for (const Door& d : map.doors) {
        j.beginObject();
        j.field("id", d.id);
        j.key("rooms").beginInlineArray().value(d.roomA).value(d.roomB).endArray();
        point(j, "jamb_a", d.jambA);
        point(j, "jamb_b", d.jambB);
        j.field("width", d.width);
        j.endObject();
    }
    j.endArray();
    j.key("adjacency").beginInlineArray();
    for (const auto& [a, b] : map.adjacency())
        j.value(a).value(b);
    j.endArray();
    // Labels: row-major runs "value, count, value, count, ..." over rows x cols cells, row 0 at
    // the top (largest y).
    j.key("labels").beginObject();
    j.field("encoding", "runs");
    j.key("runs").beginInlineArray();
    if (!map.labels.empty()) {
        int current = map.labels.at<int>(0, 0);
        long long count = 0;
        for (int r = 0; r < map.labels.rows; ++r) {
            const int* row = map.labels.ptr<int>(r);
            for (int c = 0; c < map.labels.cols; ++c) {
                if (row[c] == current) {
                    ++count;
                    continue;
                }
                j.value(current).value(count);
                current = row[c];
                count = 1;
            }
        }
        j.value(current).value(count);
    } else if (map.frame.rows > 0 && map.frame.cols > 0) {
        j.value(0).value(static_cast<long long>(map.frame.rows) *
                         map.frame.cols);  // no label image
    }
    j.endArray();
    j.endObject();
    j.endObject();
    return j.str();
}

TopologicalMap topologicalMapFromJson(const std::string& text, const std::string& sourceName) {
    try {
        const detail::JsonValue doc = detail::JsonValue::parse(text);
        if (doc.at("format", "the document").string("format") != kFormat) {
            throw detail::JsonError(std::string("format must be \"") + kFormat + "\"");
        }
        const long long version = doc.at("version", "the document").integer("version", 1, 1000);
        if (version != kVersion) {
            throw detail::JsonError("version " + std::to_string(version) +
                                    " is not supported (this reader: " + std::to_string(kVersion) +
                                    ")");
        }
        TopologicalMap map;
        const auto& frame = doc.at("frame", "the document");
        map.frame.resolution = frame.at("resolution", "frame").number("frame.resolution");
        map.frame.xMin = frame.at("x_min", "frame").number("frame.x_min");
        map.frame.yMin = frame.at("y_min", "frame").number("frame.y_min");
        map.frame.cols =
            static_cast<int>(frame.at("cols", "frame").integer("frame.cols", 0, 1 << 20));
        map.frame.rows =
            static_cast<int>(frame.at("rows", "frame").integer("frame.rows", 0, 1 << 20));
        if (!(map.frame.resolution > 0))
            throw detail::JsonError("frame.resolution must be > 0");

        const auto& rooms = doc.at("rooms", "the document").array("rooms");
        for (std::size_t i = 0; i < rooms.size(); ++i) {
            const std::string w = "rooms[" + std::to_string(i) + "]";
            Room r;
            r.id = static_cast<int>(rooms[i].at("id", w).integer(w + ".id", 1, 1 << 30));
            if (r.id != static_cast<int>(i) + 1)
                throw detail::JsonError(w + ".id must be " + std::to_string(i + 1));
            if (const auto* name = rooms[i].find("name"))
                r.name = name->string(w + ".name");
            r.area = rooms[i].at("area", w).number(w + ".area");
            r.centroid = readPoint(rooms[i].at("centroid", w), w + ".centroid");
            r.anchor = readPoint(rooms[i].at("anchor", w), w + ".anchor");
            const auto& outline = rooms[i].at("outline", w).array(w + ".outline");
            if (outline.size() % 2 != 0)
                throw detail::JsonError(w + ".outline must hold x, y pairs");
            for (std::size_t k = 0; k < outline.size(); k += 2) {
                r.outline.push_back(
                    {outline[k].number(w + ".outline"), outline[k + 1].number(w + ".outline")});
            }
            map.rooms.push_back(std::move(r));
        }
        const int roomCount = static_cast<int>(map.rooms.size());
        const auto& doors = doc.at("doors", "the document").array("doors");
        for (std::size_t i = 0; i < doors.size(); ++i) {
            const std::string w = "doors[" + std::to_string(i) + "]";
            Door d;
            d.id = static_cast<int>(doors[i].at("id", w).integer(w + ".id", 1, 1 << 30));
            if (d.id != static_cast<int>(i) + 1)
                throw detail::JsonError(w + ".id must be " + std::to_string(i + 1));
            const auto& pair = doors[i].at("rooms", w).array(w + ".rooms");
            if (pair.size() != 2)
                throw detail::JsonError(w + ".rooms must be [roomA, roomB]");
            d.roomA = static_cast<int>(pair[0].integer(w + ".rooms[0]", 1, roomCount));
            d.roomB = static_cast<int>(pair[1].integer(w + ".rooms[1]", 1, roomCount));
            if (d.roomA == d.roomB)
                throw detail::JsonError(w + " joins room " + std::to_string(d.roomA) +
                                        " to itself");
            d.jambA = readPoint(doors[i].at("jamb_a", w), w + ".jamb_a");
            d.jambB = readPoint(doors[i].at("jamb_b", w), w + ".jamb_b");
            d.width = doors[i].at("width", w).number(w + ".width");
            map.doors.push_back(d);
        }
        const auto& labels = doc.at("labels", "the document");
        if (labels.at("encoding", "labels").string("labels.encoding") != "runs") {
            throw detail::JsonError("labels.encoding must be \"runs\"");
        }
        const auto& runs = labels.at("runs", "labels").array("labels.runs");
        const long long cells = static_cast<long long>(map.frame.rows) * map.frame.cols;
        if (runs.size() % 2 != 0)
            throw detail::JsonError("labels.runs must hold value, count pairs");
        map.labels = cv::Mat(map.frame.rows, map.frame.cols, CV_32S);
        long long at = 0;
        for (std::size_t k = 0; k < runs.size(); k += 2) {
            const int value =
                static_cast<int>(runs[k].integer("labels.runs (value)", 0, roomCount));
            const long long count = runs[k + 1].integer("labels.runs (count)", 1, cells);
            if (at + count > cells)
                throw detail::JsonError("labels.runs cover more than rows x cols cells");
            std::fill_n(map.labels.ptr<int>() + at, count, value);
            at += count;
        }
        if (at != cells) {
            throw detail::JsonError("labels.runs cover " + std::to_string(at) +
                                    " cells, rows x cols is " + std::to_string(cells));
        }
        if (cells == 0)
            map.labels = cv::Mat();
        return map;
    } catch (const detail::JsonError& e) {
        throw io::InputError(sourceName, e.what());
    }
}

void saveTopologicalMapJson(const TopologicalMap& map, const std::string& path) {
    writeText(path, topologicalMapToJson(map));
}

TopologicalMap loadTopologicalMapJson(const std::string& path) {
    return topologicalMapFromJson(readText(path), path);
}

// ---- GraphML --------------------------------------------------------------------------------

namespace {

std::string xmlEscape(const std::string& s) {
    std::string out;
    for (const char c : s) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string xmlUnescape(const std::string& s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] != '&') {
            out += s[i];
            continue;
        }
        const std::size_t end = s.find(';', i);
        if (end == std::string::npos)
            throw std::runtime_error("bad entity in text");
        const std::string e = s.substr(i + 1, end - i - 1);
        if (e == "amp")
            out += '&';
        else if (e == "lt")
            out += '<';
        else if (e == "gt")
            out += '>';
        else if (e == "quot")
            out += '"';
        else if (e == "apos")
            out += '\'';
        else if (!e.empty() && e[0] == '#')
            out += static_cast<char>(
                std::stoi(e[1] == 'x' ? "0" + e.substr(1) : e.substr(1), nullptr, 0));
        else
            throw std::runtime_error("unknown entity &" + e + ";");
        i = end;
    }
    return out;
}

std::string number(double v) {
    std::ostringstream o;
    o.precision(17);
    o << v;
    return o.str();
}

struct Tag {
    std::string name;  // without '/' for closing tags
    bool closing = false, selfClosing = false;
    std::map<std::string, std::string> attributes;
};

// Parses the tag starting at text[i] == '<'; returns the index after '>'.
std::size_t parseTag(const std::string& text, std::size_t i, Tag& tag) {
    const std::size_t end = text.find('>', i);
    if (end == std::string::npos)
        throw std::runtime_error("unterminated tag");
    std::string body = text.substr(i + 1, end - i - 1);
    tag = Tag{};
    if (!body.empty() && body.back() == '/') {
        tag.selfClosing = true;
        body.pop_back();
    }
    std::size_t k = 0;
    if (!body.empty() && body[0] == '/') {
        tag.closing = true;
        k = 1;
    }
    while (k < body.size() && !std::isspace(static_cast<unsigned char>(body[k])))
        tag.name += body[k++];
    while (k < body.size()) {
        while (k < body.size() && std::isspace(static_cast<unsigned char>(body[k])))
            ++k;
        std::string key;
        while (k < body.size() && body[k] != '=' &&
               !std::isspace(static_cast<unsigned char>(body[k])))
            key += body[k++];
        while (k < body.size() &&
               (body[k] == '=' || std::isspace(static_cast<unsigned char>(body[k]))))
            ++k;
        if (key.empty())
            break;
        if (k >= body.size() || (body[k] != '"' && body[k] != '\''))
            throw std::runtime_error("attribute " + key + " without a quoted value");
        const char quote = body[k++];
        const std::size_t close = body.find(quote, k);
        if (close == std::string::npos)
            throw std::runtime_error("unterminated attribute " + key);
        tag.attributes[key] = xmlUnescape(body.substr(k, close - k));
        k = close + 1;
    }
    return end + 1;
}

}  // namespace

std::string topologicalMapToGraphML(const TopologicalMap& map) {
    std::ostringstream o;
    o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<graphml xmlns=\"http://graphml.graphdrawing.org/xmlns\"\n"
      << "         xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\"\n"
      << "         xsi:schemaLocation=\"http://graphml.graphdrawing.org/xmlns "
         "http://graphml.graphdrawing.org/xmlns/1.0/graphml.xsd\">\n";
    const char* nodeKeys[][3] = {{"room_id", "room_id", "int"},  {"name", "name", "string"},
                                 {"area", "area_m2", "double"},  {"cx", "centroid_x", "double"},
                                 {"cy", "centroid_y", "double"}, {"ax", "anchor_x", "double"},
                                 {"ay", "anchor_y", "double"}};
    const char* edgeKeys[][3] = {{"door_id", "door_id", "int"}, {"width", "width_m", "double"},
                                 {"jax", "jamb_a_x", "double"}, {"jay", "jamb_a_y", "double"},
                                 {"jbx", "jamb_b_x", "double"}, {"jby", "jamb_b_y", "double"}};
    for (const auto& k : nodeKeys) {
        o << "  <key id=\"" << k[0] << "\" for=\"node\" attr.name=\"" << k[1] << "\" attr.type=\""
          << k[2] << "\"/>\n";
    }
    for (const auto& k : edgeKeys) {
        o << "  <key id=\"" << k[0] << "\" for=\"edge\" attr.name=\"" << k[1] << "\" attr.type=\""
          << k[2] << "\"/>\n";
    }
    o << "  <graph id=\"rooms\" edgedefault=\"undirected\">\n";
    for (const Room& r : map.rooms) {
        o << "    <node id=\"r" << r.id << "\">"
          << "<data key=\"room_id\">" << r.id << "</data>"
          << "<data key=\"name\">" << xmlEscape(r.name) << "</data>"
          << "<data key=\"area\">" << number(r.area) << "</data>"
          << "<data key=\"cx\">" << number(r.centroid.x) << "</data>"
          << "<data key=\"cy\">" << number(r.centroid.y) << "</data>"
          << "<data key=\"ax\">" << number(r.anchor.x) << "</data>"
          << "<data key=\"ay\">" << number(r.anchor.y) << "</data></node>\n";
    }
    for (const Door& d : map.doors) {
        o << "    <edge id=\"d" << d.id << "\" source=\"r" << d.roomA << "\" target=\"r" << d.roomB
          << "\">"
          << "<data key=\"door_id\">" << d.id << "</data>"
          << "<data key=\"width\">" << number(d.width) << "</data>"
          << "<data key=\"jax\">" << number(d.jambA.x) << "</data>"
          << "<data key=\"jay\">" << number(d.jambA.y) << "</data>"
          << "<data key=\"jbx\">" << number(d.jambB.x) << "</data>"
          << "<data key=\"jby\">" << number(d.jambB.y) << "</data></edge>\n";
    }
    o << "  </graph>\n</graphml>\n";
    return o.str();
}

TopologicalMap topologicalMapFromGraphML(const std::string& text, const std::string& sourceName) {
    try {
        std::map<std::string, std::string> keyName;  // key id -> attr.name
        struct Element {
            std::string id, source, target;
            std::map<std::string, std::string> data;  // attr.name -> text
        };
        std::vector<Element> nodes, edges;
        Element* current = nullptr;
        std::string dataKey;
        bool sawGraph = false;
        std::size_t i = 0;
        while ((i = text.find('<', i)) != std::string::npos) {
            if (text.compare(i, 4, "<!--") == 0) {
                const std::size_t end = text.find("-->", i);
                if (end == std::string::npos)
                    throw std::runtime_error("unterminated comment");
                i = end + 3;
                continue;
            }
            if (text.compare(i, 2, "<?") == 0) {
                const std::size_t end = text.find("?>", i);
                if (end == std::string::npos)
                    throw std::runtime_error("unterminated declaration");
                i = end + 2;
                continue;
            }
            Tag tag;
            const std::size_t after = parseTag(text, i, tag);
            if (tag.name == "graph" && !tag.closing)
                sawGraph = true;
            if (tag.name == "key" && !tag.closing) {
                keyName[tag.attributes["id"]] = tag.attributes.count("attr.name")
                                                    ? tag.attributes["attr.name"]
                                                    : tag.attributes["id"];
            } else if ((tag.name == "node" || tag.name == "edge") && !tag.closing) {
                auto& list = tag.name == "node" ? nodes : edges;
                list.push_back(
                    {tag.attributes["id"], tag.attributes["source"], tag.attributes["target"], {}});
                current = tag.selfClosing ? nullptr : &list.back();
            } else if ((tag.name == "node" || tag.name == "edge") && tag.closing) {
                current = nullptr;
            } else if (tag.name == "data" && !tag.closing && current != nullptr) {
                dataKey = tag.attributes["key"];
                const std::size_t close = text.find("</data>", after);
                if (close == std::string::npos)
                    throw std::runtime_error("unterminated <data>");
                const std::string name = keyName.count(dataKey) ? keyName[dataKey] : dataKey;
                current->data[name] = xmlUnescape(text.substr(after, close - after));
                i = close + 7;
                continue;
            }
            i = after;
        }
        if (!sawGraph)
            throw std::runtime_error("no <graph> element: not a GraphML file");
        TopologicalMap map;
        std::map<std::string, int> roomOfNode;
        auto real = [](const Element& e, const std::string& name) {
            auto it = e.data.find(name);
            if (it == e.data.end())
                return 0.0;
            std::size_t used = 0;
            const double v = std::stod(it->second, &used);
            if (used != it->second.size())
                throw std::runtime_error("'" + it->second + "' is not a number (" + name + ")");
            return v;
        };
        for (const Element& n : nodes) {
            Room r;
            r.id = static_cast<int>(map.rooms.size()) + 1;
            if (!roomOfNode.emplace(n.id, r.id).second)
                throw std::runtime_error("duplicate node id '" + n.id + "'");
            if (auto it = n.data.find("name"); it != n.data.end())
                r.name = it->second;
            r.area = real(n, "area_m2");
            r.centroid = {real(n, "centroid_x"), real(n, "centroid_y")};
            r.anchor = {real(n, "anchor_x"), real(n, "anchor_y")};
            map.rooms.push_back(r);
        }
        for (const Element& e : edges) {
            Door d;
            d.id = static_cast<int>(map.doors.size()) + 1;
            auto a = roomOfNode.find(e.source), b = roomOfNode.find(e.target);
            if (a == roomOfNode.end() || b == roomOfNode.end()) {
                throw std::runtime_error("edge '" + e.id + "' joins unknown nodes '" + e.source +
                                         "', '" + e.target + "'");
            }
            if (a->second == b->second)
                throw std::runtime_error("edge '" + e.id + "' is a loop");
            d.roomA = std::min(a->second, b->second);
            d.roomB = std::max(a->second, b->second);
            d.width = real(e, "width_m");
            d.jambA = {real(e, "jamb_a_x"), real(e, "jamb_a_y")};
            d.jambB = {real(e, "jamb_b_x"), real(e, "jamb_b_y")};
            map.doors.push_back(d);
        }
        return map;
    } catch (const std::exception& e) {
        throw io::InputError(sourceName, std::string("GraphML: ") + e.what());
    }
}

void saveTopologicalMapGraphML(const TopologicalMap& map, const std::string& path) {
    writeText(path, topologicalMapToGraphML(map));
}

TopologicalMap loadTopologicalMapGraphML(const std::string& path) {
    return topologicalMapFromGraphML(readText(path), path);
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
