#include <toposlam/evaluation/SlamBenchmarkLog.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace toposlam::evaluation {

std::vector<SlamBenchmarkLog> findRelationLogs(const std::string& directory) {
    namespace fs = std::filesystem;
    std::vector<SlamBenchmarkLog> logs;
    std::error_code ec;
    if (!fs::is_directory(directory, ec))
        return logs;
    for (const fs::directory_entry& entry : fs::directory_iterator(directory, ec)) {
        const fs::path& relations = entry.path();
        if (relations.extension() != ".relations" || !entry.is_regular_file(ec))
            continue;
        for (const char* extension :
             {".clf", ".log", ".rawlog", ".clf.gz", ".log.gz", ".rawlog.gz"}) {
            const fs::path log = relations.parent_path() / (relations.stem().string() + extension);
            if (fs::is_regular_file(log, ec)) {
                logs.push_back(
                    {relations.stem().string(), log.string(), relations.string(), "", ""});
                break;
            }
        }
    }
    std::sort(logs.begin(), logs.end(),
              [](const SlamBenchmarkLog& a, const SlamBenchmarkLog& b) { return a.name < b.name; });
    return logs;
}

}  // namespace toposlam::evaluation
