#pragma once
// Fast line-by-line reading of a text file (plain or gzip) through a large buffer: the
// CARMEN reader touches every byte of logs of tens of megabytes.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "GzipInputStream.h"

namespace toposlam::io {

class LineReader {
  public:
    explicit LineReader(const std::string& path);

    /// The next line without its '\n' (and '\r'); valid until the next call. False at the end.
    bool next(std::string_view& line);
    /// 1-based number of the line last returned.
    std::size_t lineNumber() const { return lineNumber_; }
    /// Decompressed bytes of the lines returned so far (including their line ends).
    uint64_t bytesParsed() const { return in_.bytesDelivered() - (end_ - begin_); }
    /// Fraction of the file's content returned as lines so far, in [0,1].
    double fractionRead() const { return in_.fractionAt(bytesParsed()); }
    /// The exact decompressed size of the file, when known (see GzipInputStream).
    void setDecompressedSize(uint64_t bytes) { in_.setDecompressedSize(bytes); }
    /// See GzipInputStream::streamError().
    std::string streamError() const { return in_.streamError(); }

  private:
    GzipInputStream in_;
    std::vector<char> buffer_;
    std::size_t begin_ = 0, end_ = 0;  // unread bytes are buffer_[begin_, end_)
    bool eof_ = false;
    std::size_t lineNumber_ = 0;
};

}  // namespace toposlam::io
