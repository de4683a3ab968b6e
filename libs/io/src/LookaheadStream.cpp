#include "LookaheadStream.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace toposlam::io {

namespace {
constexpr std::size_t kChunk = 1 << 20;  // bytes pulled from the file at a time, at most
}  // namespace

bool LookaheadStream::ensure(std::size_t count) {
    if (begin_ > 0 && begin_ == buffer_.size()) {
        buffer_.clear();
        begin_ = 0;
    }
    while (buffered() < count) {
        const std::size_t want = std::min(count - buffered(), kChunk);
        const std::size_t old = buffer_.size();
        buffer_.resize(old + want);
        const std::size_t got = file_.Read(buffer_.data() + old, want);
        buffer_.resize(old + got);
        if (got == 0)
            return false;
    }
    return true;
}

size_t LookaheadStream::Read(void* buffer, size_t count) {
    if (limit_)
        count = std::min(count, *limit_);
    auto* out = static_cast<unsigned char*>(buffer);
    const std::size_t fromBuffer = std::min(count, buffered());
    if (fromBuffer > 0) {
        std::memcpy(out, ahead(), fromBuffer);
        begin_ += fromBuffer;
    }
    std::size_t total = fromBuffer;
    if (total < count && !limit_)
        total += file_.Read(out + total, count - total);
    if (limit_)
        *limit_ -= total;
    position_ += total;
    return total;
}

size_t LookaheadStream::Write(const void*, size_t) {
    throw std::logic_error("LookaheadStream is read-only");
}

uint64_t LookaheadStream::Seek(int64_t, TSeekOrigin) {
    throw std::logic_error("LookaheadStream cannot seek");
}

}  // namespace toposlam::io
