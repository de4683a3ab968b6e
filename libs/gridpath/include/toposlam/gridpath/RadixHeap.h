#pragma once
// A radix heap (Ahuja, Mehlhorn, Orlin and Tarjan, "Faster algorithms for the shortest path
// problem", J. ACM 1990): the priority queue of Dijkstra's search, where no key pushed is below
// the last key popped. Keys are non-negative floats, whose bit patterns order as their values;
// an entry sits in the bucket of the highest bit in which its key differs from the last popped,
// so a pop only sorts out one bucket and each entry moves down at most 32 times. Entries of
// equal key come out in no particular order: fine for Dijkstra, whose costs do not depend on
// it, not for A*'s choice between equal-cost paths.
#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

namespace toposlam::gridpath {

class RadixHeap {
  public:
    bool empty() const { return size_ == 0; }

    /// Empties the heap; the next key pushed may be any.
    void clear() {
        for (auto& b : buckets_)
            b.clear();
        size_ = 0;
        last_ = 0;
    }

    /// `key` >= 0 and >= the last key popped.
    void push(float key, std::uint32_t cell) {
        const std::uint32_t bits = bitsOf(key);
        buckets_[bucketOf(bits)].push_back({bits, cell});
        ++size_;
    }

    /// The cell of a smallest key, removed. Not empty().
    std::uint32_t pop() {
        if (buckets_[0].empty()) {
            std::size_t b = 1;
            while (buckets_[b].empty())
                ++b;
            std::vector<Entry>& from = buckets_[b];
            std::uint32_t least = from.front().bits;
            for (const Entry& e : from)
                least = e.bits < least ? e.bits : least;
            last_ = least;
            for (const Entry& e : from)
                buckets_[bucketOf(e.bits)].push_back(e);  // all into lower buckets
            from.clear();
        }
        const std::uint32_t cell = buckets_[0].back().cell;
        buckets_[0].pop_back();
        --size_;
        return cell;
    }

  private:
    struct Entry {
        std::uint32_t bits;
        std::uint32_t cell;
    };
    static std::uint32_t bitsOf(float key) {
        std::uint32_t bits;
        std::memcpy(&bits, &key, sizeof bits);
        return bits;
    }
    std::size_t bucketOf(std::uint32_t bits) const {
        return bits == last_ ? 0 : 32 - static_cast<std::size_t>(__builtin_clz(bits ^ last_));
    }

    std::array<std::vector<Entry>, 33> buckets_;
    std::uint32_t last_ = 0;  ///< bits of the last key popped
    std::size_t size_ = 0;
};

}  // namespace toposlam::gridpath
