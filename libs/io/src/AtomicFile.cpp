#include <toposlam/io/AtomicFile.h>

#include <unistd.h>

#include <atomic>
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
    const std::string tmp =
        stem + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ext;
    return (p.parent_path() / tmp).string();
}

}  // namespace

TemporaryOutputFile::TemporaryOutputFile(std::string path)
    : path_(std::move(path)), tmpPath_(temporaryNameFor(path_)) {}

TemporaryOutputFile::~TemporaryOutputFile() {
    if (committed_)
        return;
    std::error_code ignored;
    fs::remove(tmpPath_, ignored);
}

void TemporaryOutputFile::commit() {
    std::error_code ec;
    fs::rename(tmpPath_, path_, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(tmpPath_, ignored);
        throw std::runtime_error(path_ + ": cannot write the output file (" + ec.message() + ")");
    }
    committed_ = true;
}

void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tmpPath)>& writeTo) {
    TemporaryOutputFile out(path);
    writeTo(out.temporaryPath());
    out.commit();
}

}  // namespace toposlam::io
