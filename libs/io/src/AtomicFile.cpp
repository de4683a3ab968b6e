#include <toposlam/io/AtomicFile.h>

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace toposlam::io {

namespace fs = std::filesystem;

namespace {

// "dir/map.gridmap.gz" -> "dir/map.tmp-<pid>-<n>.gridmap.gz": same directory (rename stays
// atomic, same filesystem) and same compound extension (writers that look at it still work).
std::string temporaryNameFor(const std::string& path) {
    static std::atomic<unsigned> counter{0};
    const fs::path p(path);
    const std::string name = p.filename().string();
    const auto dot = name.find('.', 1);
    const std::string stem = name.substr(0, dot);
    const std::string ext = dot == std::string::npos ? "" : name.substr(dot);
    const std::string tmp = stem + ".tmp-" + std::to_string(::getpid()) + "-" +
                            std::to_string(counter++) + ext;
    return (p.parent_path() / tmp).string();
}

}  // namespace

void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tmpPath)>& writeTo) {
    const std::string tmp = temporaryNameFor(path);
    try {
        writeTo(tmp);
    } catch (...) {
        std::error_code ignored;
        fs::remove(tmp, ignored);
        throw;
    }
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw std::runtime_error(path + ": cannot write the output file (" + ec.message() + ")");
    }
}

}  // namespace toposlam::io
