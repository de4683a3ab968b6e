#include "LineReader.h"

#include <cstring>

namespace toposlam::io {

LineReader::LineReader(const std::string& path) : in_(path), buffer_(1 << 20) {}

bool LineReader::next(std::string_view& line) {
    while (true) {
        const char* start = buffer_.data() + begin_;
        const void* nl = std::memchr(start, '\n', end_ - begin_);
        if (nl || (eof_ && begin_ < end_)) {
            const char* stop = nl ? static_cast<const char*>(nl) : buffer_.data() + end_;
            std::size_t len = static_cast<std::size_t>(stop - start);
            begin_ += len + (nl ? 1 : 0);
            if (len > 0 && start[len - 1] == '\r')
                --len;
            line = std::string_view(start, len);
            ++lineNumber_;
            return true;
        }
        if (eof_)
            return false;
        // Move the partial line to the front; grow the buffer for very long lines.
        std::memmove(buffer_.data(), start, end_ - begin_);
        end_ -= begin_;
        begin_ = 0;
        if (end_ == buffer_.size())
            buffer_.resize(buffer_.size() * 2);
        const std::size_t n = in_.Read(buffer_.data() + end_, buffer_.size() - end_);
        if (n == 0)
            eof_ = true;
        end_ += n;
    }
}

}  // namespace toposlam::io
