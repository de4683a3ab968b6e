#pragma once
// An MRPT input stream that lets TopoSLAM look at the bytes of the next serialized object
// before MRPT deserializes them (MrptObjectCheck.h). Bytes are pulled from the file on demand
// into a buffer, in chunks, so the buffer never holds more than the file really has however
// large a length field claims to be. MRPT then reads the buffer first and, for an object that
// was only partly checked, the rest of the file after it.
#include <mrpt/io/CStream.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "GzipInputStream.h"

namespace toposlam::io {

class LookaheadStream : public mrpt::io::CStream {
  public:
    explicit LookaheadStream(GzipInputStream& file) : file_(file) {}

    /// Makes `count` bytes after the read position available through ahead(); false if the
    /// file ends first (then ahead() holds all that is left).
    bool ensure(std::size_t count);
    /// The bytes after the read position that are buffered (see ensure()).
    const unsigned char* ahead() const { return buffer_.data() + begin_; }
    std::size_t buffered() const { return buffer_.size() - begin_; }
    /// Until cleared (nullopt), Read() ends after `count` more bytes, as at the end of the
    /// file: MRPT may read only the bytes that were checked.
    void setReadLimit(std::optional<std::size_t> count) { limit_ = count; }
    /// Decompressed bytes read through this stream so far (the position in the content).
    uint64_t position() const { return position_; }
    /// Fraction of the file's content read through this stream, in [0,1].
    double fractionRead() const { return file_.fractionAt(position_); }

    size_t Read(void* buffer, size_t count) override;
    size_t Write(const void* buffer, size_t count) override;
    uint64_t Seek(int64_t offset, TSeekOrigin origin) override;
    uint64_t getTotalBytesCount() const override { return file_.getTotalBytesCount(); }
    uint64_t getPosition() const override { return position_; }
    std::string getStreamDescription() const override { return file_.path(); }

  private:
    GzipInputStream& file_;
    std::vector<unsigned char> buffer_;
    std::size_t begin_ = 0;  // read position in buffer_
    std::optional<std::size_t> limit_;
    uint64_t position_ = 0;
};

}  // namespace toposlam::io
