#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/FileExtension.h>

#include <sys/statvfs.h>
#include <unistd.h>
#include <zlib.h>

#include <array>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace toposlam::io {

namespace fs = std::filesystem;

namespace {

// The group that writes on this thread belong to (nullptr: rename each file when written).
thread_local OutputGroup* tActiveGroup = nullptr;

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

// A PNG ends with its IEND chunk (empty, so its length and CRC are fixed).
bool pngIsComplete(const std::string& file) {
    static constexpr std::array<char, 12> kIend = {0,   0,   0,      0,   'I', 'E',
                                                   'N', 'D', '\xAE', 'B', '`', '\x82'};
    std::ifstream in(file, std::ios::binary | std::ios::ate);
    if (!in || in.tellg() < static_cast<std::streamoff>(kIend.size()))
        return false;
    std::array<char, 12> tail{};
    in.seekg(-static_cast<std::streamoff>(tail.size()), std::ios::end);
    in.read(tail.data(), static_cast<std::streamsize>(tail.size()));
    return in && tail == kIend;
}

// A gzip file starts with its magic bytes and decompresses to its end (zlib checks each
// member's CRC and length, and reports a stream cut short).
bool gzipIsComplete(const std::string& file) {
    {
        std::ifstream in(file, std::ios::binary);
        std::array<unsigned char, 2> magic{};
        in.read(reinterpret_cast<char*>(magic.data()), 2);
        if (!in || magic[0] != 0x1f || magic[1] != 0x8b)
            return false;
    }
    gzFile gz = gzopen(file.c_str(), "rb");
    if (gz == nullptr)
        return false;
    std::vector<char> buffer(1 << 16);
    int n = 0;
    while ((n = gzread(gz, buffer.data(), static_cast<unsigned>(buffer.size()))) > 0) {
    }
    int code = Z_OK;
    gzerror(gz, &code);
    gzclose_r(gz);
    return n == 0 && code == Z_OK;
}

// No block left (root's reserve included). Filesystems that report no blocks at all (some FUSE
// and pseudo filesystems) are not judged.
bool deviceFull(const std::string& file) {
    struct statvfs device {};
    return ::statvfs(file.c_str(), &device) == 0 && device.f_blocks > 0 && device.f_bfree == 0;
}

// cv::imwrite and MRPT's gzip stream close their files without checking, so a full disk leaves
// a truncated file that they report as written. What is on disk is checked before the rename.
void checkWritten(const std::string& tmp, const std::string& path) {
    if (deviceFull(tmp))
        throw std::runtime_error(path + ": cannot write the file (no space left on the device)");
    if (hasExtension(path, ".png") && !pngIsComplete(tmp))
        throw std::runtime_error(path + ": cannot write the file (the PNG came out truncated)");
    if (hasExtension(path, ".gz") && !gzipIsComplete(tmp))
        throw std::runtime_error(path +
                                 ": cannot write the file (the gzip data came out truncated)");
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
    try {
        checkWritten(tmpPath_, path_);
    } catch (...) {
        std::error_code ignored;
        fs::remove(tmpPath_, ignored);
        throw;
    }
    if (tActiveGroup) {
        tActiveGroup->add(tmpPath_, path_);
        committed_ = true;  // the group owns the temporary file now
        return;
    }
    std::error_code ec;
    fs::rename(tmpPath_, path_, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(tmpPath_, ignored);
        throw std::runtime_error(path_ + ": cannot write the output file (" + ec.message() + ")");
    }
    committed_ = true;
}

OutputGroup::OutputGroup() : outer_(tActiveGroup) {
    tActiveGroup = this;
}

OutputGroup::~OutputGroup() {
    tActiveGroup = outer_;
    if (committed_)
        return;
    std::error_code ignored;
    for (const auto& file : files_)
        fs::remove(file.first, ignored);
}

void OutputGroup::add(std::string temporaryPath, std::string path) {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (auto& file : files_) {
        if (file.second == path) {
            std::error_code ignored;
            fs::remove(file.first, ignored);
            file.first = std::move(temporaryPath);
            return;
        }
    }
    files_.emplace_back(std::move(temporaryPath), std::move(path));
}

void OutputGroup::commit() {
    const std::lock_guard<std::mutex> lock(mutex_);
    tActiveGroup = outer_;
    if (!outer_) {
        // rename(2) cannot replace a folder: find that before the first rename, not after.
        for (const auto& file : files_) {
            std::error_code ec;
            if (fs::is_directory(file.second, ec))
                throw std::runtime_error(file.second +
                                         ": cannot write the output file (a folder has that name)");
        }
    }
    committed_ = true;
    for (std::size_t i = 0; i < files_.size(); ++i) {
        const auto& [temporaryPath, path] = files_[i];
        if (outer_) {
            outer_->add(temporaryPath, path);
            continue;
        }
        std::error_code ec;
        fs::rename(temporaryPath, path, ec);
        if (ec) {
            std::error_code ignored;
            for (std::size_t j = i; j < files_.size(); ++j)
                fs::remove(files_[j].first, ignored);
            throw std::runtime_error(path + ": cannot write the output file (" + ec.message() +
                                     ")");
        }
    }
}

OutputGroup::ThreadMembership::ThreadMembership(OutputGroup& group) : previous_(tActiveGroup) {
    tActiveGroup = &group;
}

OutputGroup::ThreadMembership::~ThreadMembership() {
    tActiveGroup = previous_;
}

void rethrowWriteError(const std::string& path) {
    try {
        throw;
    } catch (const std::exception& e) {
        // MRPT's streams report a failed write(2) so, with a call stack and no file name.
        if (std::string(e.what()).find("Cannot write bytes to stream") == std::string::npos)
            throw;
        const fs::path directory = fs::path(path).parent_path();
        const bool full = deviceFull(directory.empty() ? "." : directory.string());
        throw std::runtime_error(path + ": cannot write the file (" +
                                 (full ? "no space left on the device" : "write error") + ")");
    }
}

void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tmpPath)>& writeTo) {
    TemporaryOutputFile out(path);
    try {
        writeTo(out.temporaryPath());
    } catch (...) {
        rethrowWriteError(path);
    }
    out.commit();
}

}  // namespace toposlam::io
