#include <toposlam/io/FileExtension.h>
#include <toposlam/io/InputError.h>
#include <toposlam/rooms/TopologicalMapIO.h>

#include <stdexcept>

namespace toposlam::rooms {

void saveTopologicalMap(const TopologicalMap& map, const std::string& path) {
    if (io::hasExtension(path, ".json"))
        return saveTopologicalMapJson(map, path);
    if (io::hasExtension(path, ".graphml"))
        return saveTopologicalMapGraphML(map, path);
    throw std::invalid_argument(path + ": unknown topological-map format (use .json or .graphml)");
}

TopologicalMap loadTopologicalMap(const std::string& path) {
    if (io::hasExtension(path, ".json"))
        return loadTopologicalMapJson(path);
    if (io::hasExtension(path, ".graphml"))
        return loadTopologicalMapGraphML(path);
    throw io::InputError(path, "unknown topological-map format (use .json or .graphml)");
}

}  // namespace toposlam::rooms
