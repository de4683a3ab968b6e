#pragma once
// An MRPT input stream over a file that may or may not be gzip-compressed (zlib reads plain
// files transparently). Unlike mrpt::io::CFileGZInputStream it knows the decompressed size of
// the file (plain: its size; gzip: the size its trailer states), so that readers can report
// progress as the fraction of the content they have parsed, and it can tell a clean end of a
// gzip stream from a truncated or corrupt one, which zlib only reports through gzerror().
#include <mrpt/io/CStream.h>

#include <cstdint>
#include <string>

namespace toposlam::io {

class GzipInputStream : public mrpt::io::CStream {
  public:
    /// Throws InputError(path, ...) when the file is missing or cannot be opened.
    explicit GzipInputStream(const std::string& path);
    ~GzipInputStream() override;
    GzipInputStream(const GzipInputStream&) = delete;
    GzipInputStream& operator=(const GzipInputStream&) = delete;

    size_t Read(void* buffer, size_t count) override;
    size_t Write(const void* buffer, size_t count) override;
    uint64_t Seek(int64_t offset, TSeekOrigin origin) override;
    /// Size of the file on disk (compressed size for .gz).
    uint64_t getTotalBytesCount() const override;
    /// Bytes of the file on disk consumed so far.
    uint64_t getPosition() const override;
    std::string getStreamDescription() const override;

    /// Decompressed bytes returned by Read() so far.
    uint64_t bytesDelivered() const { return delivered_; }
    /// The fraction of the file's content, in [0,1], that lies before decompressed position
    /// `position` (bytes a reader has parsed, which trail bytesDelivered() by what it buffers).
    /// Falls back to the compressed bytes zlib has pulled when the decompressed size is
    /// unknown (gzip files over 4 GiB, several gzip members).
    double fractionAt(uint64_t position) const;
    /// Sets the exact decompressed size, when a reader has measured it (a first pass).
    void setDecompressedSize(uint64_t bytes) { decompressedSize_ = bytes; }
    /// True if the file is gzip-compressed.
    bool compressed() const { return compressed_; }
    /// Empty if the data read so far was intact; otherwise zlib's description of the damage
    /// (e.g. "unexpected end of file" for a truncated .gz).
    std::string streamError() const;
    const std::string& path() const { return path_; }

  private:
    std::string path_;
    void* file_ = nullptr;  // gzFile
    uint64_t size_ = 0;
    uint64_t decompressedSize_ = 0;  // 0: unknown
    uint64_t delivered_ = 0;
    bool compressed_ = false;
};

}  // namespace toposlam::io
