#include <toposlam/io/InputError.h>
#include <toposlam/rooms/TopologicalMapIO.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace toposlam::rooms {

namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           std::equal(suffix.rbegin(), suffix.rend(), s.rbegin(),
                      [](char a, char b) { return std::tolower(a) == std::tolower(b); });
}

}  // namespace

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
