#include "GzipInputStream.h"

#include <toposlam/io/InputError.h>
#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace toposlam::io {

namespace fs = std::filesystem;

namespace {
gzFile asGz(void* f) {
    return static_cast<gzFile>(f);
}

// The decompressed size a gzip file states in its last 4 bytes (ISIZE, modulo 2^32), or 0.
uint64_t gzipStatedSize(std::FILE* f, uint64_t fileSize) {
    unsigned char tail[4];
    if (fileSize < 18 || std::fseek(f, -4, SEEK_END) != 0 || std::fread(tail, 1, 4, f) != 4)
        return 0;
    return uint64_t{tail[0]} | uint64_t{tail[1]} << 8 | uint64_t{tail[2]} << 16 |
           uint64_t{tail[3]} << 24;
}
}  // namespace

GzipInputStream::GzipInputStream(const std::string& path) : path_(path) {
    std::error_code ec;
    if (!fs::exists(path, ec))
        throw InputError(path, "file not found");
    if (fs::is_directory(path, ec))
        throw InputError(path, "is a directory, not a file");
    size_ = fs::file_size(path, ec);
    if (ec)
        throw InputError(path, "cannot read the file size (" + ec.message() + ")");
    if (std::FILE* probe = std::fopen(path.c_str(), "rb")) {
        unsigned char magic[2] = {0, 0};
        compressed_ = std::fread(magic, 1, 2, probe) == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
        decompressedSize_ = compressed_ ? gzipStatedSize(probe, size_) : size_;
        std::fclose(probe);
    } else {
        throw InputError(path, "cannot open the file (permission denied?)");
    }
    file_ = gzopen(path.c_str(), "rb");
    if (!file_)
        throw InputError(path, "cannot open the file");
    gzbuffer(asGz(file_), 256 * 1024);  // fewer system calls than zlib's 8 KiB default
}

GzipInputStream::~GzipInputStream() {
    if (file_)
        gzclose(asGz(file_));
}

size_t GzipInputStream::Read(void* buffer, size_t count) {
    size_t total = 0;
    auto* out = static_cast<unsigned char*>(buffer);
    while (total < count) {
        const unsigned chunk = static_cast<unsigned>(std::min<size_t>(count - total, 1u << 30));
        const int n = gzread(asGz(file_), out + total, chunk);
        if (n <= 0)
            break;  // end of data or error (see streamError())
        total += static_cast<size_t>(n);
    }
    delivered_ += total;
    return total;
}

size_t GzipInputStream::Write(const void*, size_t) {
    throw std::logic_error("GzipInputStream is read-only");
}

uint64_t GzipInputStream::Seek(int64_t, TSeekOrigin) {
    throw std::logic_error("GzipInputStream cannot seek");
}

uint64_t GzipInputStream::getTotalBytesCount() const {
    return size_;
}

uint64_t GzipInputStream::getPosition() const {
    // gzoffset: position in the file on disk (compressed bytes for .gz, bytes otherwise),
    // including zlib's read-ahead buffer.
    const auto pos = gzoffset(asGz(file_));
    return pos < 0 ? 0 : static_cast<uint64_t>(pos);
}

std::string GzipInputStream::getStreamDescription() const {
    return path_;
}

double GzipInputStream::fractionAt(uint64_t position) const {
    if (size_ == 0)
        return 1.0;
    // A stated gzip size below what has already been delivered is wrong (ISIZE wraps at 4 GiB).
    if (decompressedSize_ > 0 && decompressedSize_ >= delivered_) {
        return std::min(1.0,
                        static_cast<double>(position) / static_cast<double>(decompressedSize_));
    }
    return std::min(1.0, static_cast<double>(getPosition()) / static_cast<double>(size_));
}

std::string GzipInputStream::streamError() const {
    int code = Z_OK;
    const char* msg = gzerror(asGz(file_), &code);
    if (code == Z_OK || code == Z_STREAM_END)
        return {};
    std::string text = msg && *msg ? msg : "zlib error " + std::to_string(code);
    // zlib prefixes the message with the path, which the caller's message names already.
    if (text.rfind(path_ + ": ", 0) == 0)
        text.erase(0, path_.size() + 2);
    return text;
}

}  // namespace toposlam::io
