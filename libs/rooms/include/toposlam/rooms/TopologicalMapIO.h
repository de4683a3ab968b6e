#pragma once
// Topological maps on disk.
//   .json     everything: frame, rooms (with outline), doors, adjacency and the label image
//             (run-length encoded); schema in share/doc/file-formats.md, "Topological map".
//   .graphml  the graph for graph tools (networkx, yEd, Gephi): rooms as nodes (name, area,
//             centroid, anchor, outline), doors as undirected edges (id, width, jambs), and as
//             graph attributes the frame and the label image (runs), so it plans like .json.
// Both are read and written with Debian's libraries (nlohmann-json, tinyxml2). Writers are
// atomic (no partial file on failure); readers throw toposlam::io::InputError naming the file
// and the problem.
#include <toposlam/rooms/TopologicalMap.h>

#include <string>

namespace toposlam::rooms {

std::string topologicalMapToJson(const TopologicalMap& map);
/// `sourceName` names the text in error messages.
TopologicalMap topologicalMapFromJson(const std::string& text, const std::string& sourceName);
void saveTopologicalMapJson(const TopologicalMap& map, const std::string& path);
TopologicalMap loadTopologicalMapJson(const std::string& path);

std::string topologicalMapToGraphML(const TopologicalMap& map);
/// Node, edge and graph attributes are found by name (attr.name), so files from other GraphML
/// writers work when they use the same names; without the graph attributes cols/rows (and
/// label_runs) the returned map has no frame (and no label image), without outline attributes
/// no outlines.
TopologicalMap topologicalMapFromGraphML(const std::string& text, const std::string& sourceName);
void saveTopologicalMapGraphML(const TopologicalMap& map, const std::string& path);
TopologicalMap loadTopologicalMapGraphML(const std::string& path);

/// By extension: .json or .graphml. Throws std::invalid_argument for another extension.
void saveTopologicalMap(const TopologicalMap& map, const std::string& path);
TopologicalMap loadTopologicalMap(const std::string& path);

}  // namespace toposlam::rooms
