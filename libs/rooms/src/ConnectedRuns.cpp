#include <toposlam/rooms/ConnectedRuns.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace toposlam::rooms {

namespace {

// Eight cells at a time: runs are long, so most of a row is skipped a word at a time.
std::uint64_t load8(const std::uint8_t* cells) {
    std::uint64_t word;
    std::memcpy(&word, cells, sizeof word);
    return word;
}

bool hasZeroCell(std::uint64_t word) {
    return ((word - 0x0101010101010101ULL) & ~word & 0x8080808080808080ULL) != 0;
}

// Whether none (All = false) or all (All = true) of eight cells are in the set.
template <bool NonZero, bool All>
bool eightCells(std::uint64_t word) {
    const bool allZero = word == 0, noneZero = !hasZeroCell(word);
    if constexpr (NonZero == All)
        return noneZero;
    else
        return allZero;
}

}  // namespace

template <bool NonZero>
void ConnectedRuns::collectRuns(const cv::Mat& image) {
    const auto inSet = [](std::uint8_t v) { return (v != 0) == NonZero; };
    const int cols = image.cols;
    for (int r = 0; r < image.rows; ++r) {
        rowStart_[static_cast<std::size_t>(r)] = static_cast<int>(runs_.size());
        const std::uint8_t* row = image.ptr<std::uint8_t>(r);
        for (int c = 0; c < cols;) {
            while (c + 8 <= cols && eightCells<NonZero, false>(load8(row + c)))
                c += 8;
            while (c < cols && !inSet(row[c]))
                ++c;
            if (c == cols)
                break;
            const int begin = c;
            while (c + 8 <= cols && eightCells<NonZero, true>(load8(row + c)))
                c += 8;
            while (c < cols && inSet(row[c]))
                ++c;
            runs_.push_back({r, begin, c, 0});
        }
    }
    rowStart_[static_cast<std::size_t>(image.rows)] = static_cast<int>(runs_.size());
}

int ConnectedRuns::root(int run) {
    // Path halving: every other run on the way points two steps up.
    while (parent_[static_cast<std::size_t>(run)] != run) {
        int& up = parent_[static_cast<std::size_t>(run)];
        up = parent_[static_cast<std::size_t>(up)];
        run = up;
    }
    return run;
}

int ConnectedRuns::find(const cv::Mat& image, int connectivity, Cells cells) {
    CV_Assert(image.type() == CV_8U && (connectivity == 4 || connectivity == 8));
    size_ = image.size();
    runs_.clear();
    rowStart_.resize(static_cast<std::size_t>(image.rows) + 1);
    if (cells == Cells::NonZero) {
        collectRuns<true>(image);
    } else {
        collectRuns<false>(image);
    }
    const int n = static_cast<int>(runs_.size());
    parent_.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        parent_[static_cast<std::size_t>(i)] = i;

    // Two runs of neighbouring rows touch when their columns overlap (4-connected) or overlap
    // or meet at a corner (8-connected). Both rows' runs are in column order: one sweep.
    const int reach = connectivity == 8 ? 1 : 0;
    for (int r = 1; r < image.rows; ++r) {
        int above = rowStart_[static_cast<std::size_t>(r) - 1];
        const int aboveEnd = rowStart_[static_cast<std::size_t>(r)];
        const int end = rowStart_[static_cast<std::size_t>(r) + 1];
        for (int i = aboveEnd; i < end && above < aboveEnd; ++i) {
            const Run& run = runs_[static_cast<std::size_t>(i)];
            while (above < aboveEnd &&
                   runs_[static_cast<std::size_t>(above)].end + reach <= run.begin)
                ++above;
            for (int k = above;
                 k < aboveEnd && runs_[static_cast<std::size_t>(k)].begin < run.end + reach; ++k) {
                const int a = root(i), b = root(k);
                // The lower index is the root, so that a component's root is its first run.
                if (a < b) {
                    parent_[static_cast<std::size_t>(b)] = a;
                } else if (b < a) {
                    parent_[static_cast<std::size_t>(a)] = b;
                }
            }
        }
    }

    // Labels in the order of the components' first runs (= first cells in raster order): a
    // run's parent comes before it, so its label is known.
    int labels = 1;
    areas_.assign(1, 0);
    for (int i = 0; i < n; ++i) {
        Run& run = runs_[static_cast<std::size_t>(i)];
        const int up = parent_[static_cast<std::size_t>(i)];
        if (up == i) {
            run.label = labels++;
            areas_.push_back(0);
        } else {
            run.label = runs_[static_cast<std::size_t>(up)].label;
        }
        areas_[static_cast<std::size_t>(run.label)] += run.end - run.begin;
    }
    return labels;
}

void ConnectedRuns::paint(cv::Mat& labels) const {
    labels.create(size_, CV_32S);
    for (int r = 0; r < size_.height; ++r) {
        int* row = labels.ptr<int>(r);
        int c = 0;
        const int end = rowStart_[static_cast<std::size_t>(r) + 1];
        for (int i = rowStart_[static_cast<std::size_t>(r)]; i < end; ++i) {
            const Run& run = runs_[static_cast<std::size_t>(i)];
            std::fill(row + c, row + run.begin, 0);
            std::fill(row + run.begin, row + run.end, run.label);
            c = run.end;
        }
        std::fill(row + c, row + size_.width, 0);
    }
}

}  // namespace toposlam::rooms
