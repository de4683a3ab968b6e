#include <toposlam/features/SplitAndMergeExtractor.h>

#include <algorithm>
#include <cmath>
#include <ostream>

namespace toposlam::features {

void SplitAndMergeOptions::declare(config::OptionsSchema& s) {
    s.real("split_distance", splitDistance, "m", "floor of the split threshold").above(0);
    s.real("noise_sigmas", noiseSigmas, "",
           "split threshold = max(split_distance, noise_sigmas * range noise)")
        .atLeast(0);
    s.real("range_noise_std", rangeNoiseStd, "m", "range noise when the scan does not state it")
        .atLeast(0);
    s.flag("use_scan_std_error", useScanStdError,
           "take the range noise from the scan's stdError field instead");
    s.real("min_valid_range", minValidRange, "m", "readings at or below are invalid").atLeast(0);
    s.group("jump_", jumps);
    s.group("", assembly);
}

double SplitAndMergeExtractor::rangeNoise(const mrpt::obs::CObservation2DRangeScan& scan) const {
    const double s = options.useScanStdError ? scan.stdError : options.rangeNoiseStd;
    return std::isfinite(s) && s > 0 ? s : 0.0;
}

bool SplitAndMergeExtractor::farthest(std::size_t begin, std::size_t end, double threshold,
                                      std::size_t& at) const {
    if (end < begin + 2)
        return false;
    const double ax = points_.x(begin), ay = points_.y(begin);
    const double dx = points_.x(end) - ax, dy = points_.y(end) - ay;
    // |cross| / |chord| is the distance; compare squares, no division per reading.
    double best = threshold * threshold * (dx * dx + dy * dy);
    bool found = false;
    for (std::size_t k = begin + 1; k < end; ++k) {
        const double c = dx * (points_.y(k) - ay) - dy * (points_.x(k) - ax);
        if (c * c > best) {
            best = c * c;
            at = k;
            found = true;
        }
    }
    return found;
}

void SplitAndMergeExtractor::splitRun(const PointRun& run, double threshold) {
    // Split, left to right: the right half is pushed first so the left one is done first.
    const std::size_t first = parts_.size();
    stack_.clear();
    stack_.emplace_back(run.begin, run.end);
    while (!stack_.empty()) {
        const auto [b, e] = stack_.back();
        stack_.pop_back();
        std::size_t k = 0;
        if (farthest(b, e, threshold, k)) {
            stack_.emplace_back(static_cast<std::uint32_t>(k), e);
            stack_.emplace_back(b, static_cast<std::uint32_t>(k));
        } else {
            LinePart p;
            p.begin = b;
            p.end = e;
            p.cornerAfter = e != run.end;
            p.joint = e;
            parts_.push_back(p);
        }
    }
    // Merge neighbours whose union is one line by the same test.
    std::size_t out = first;
    for (std::size_t i = first + 1; i < parts_.size(); ++i) {
        std::size_t k = 0;
        if (!farthest(parts_[out].begin, parts_[i].end, threshold, k)) {
            parts_[out].end = parts_[i].end;
            parts_[out].cornerAfter = parts_[i].cornerAfter;
            parts_[out].joint = parts_[i].joint;
        } else {
            parts_[++out] = parts_[i];
        }
    }
    parts_.resize(out + 1);
    parts_[first].beginType = run.beginType;
    parts_.back().endType = run.endType;
    // The split reading is shared by both parts: leave it out of both fits.
    for (std::size_t i = first; i + 1 < parts_.size(); ++i) {
        if (parts_[i].end > parts_[i].begin)
            --parts_[i].end;
        if (parts_[i + 1].begin < parts_[i + 1].end)
            ++parts_[i + 1].begin;
    }
}

void SplitAndMergeExtractor::extract(const mrpt::obs::CObservation2DRangeScan& scan,
                                     ScanFeatures& out) {
    const double sigma = rangeNoise(scan);
    points_.assign(scan, options.minValidRange);
    jumpDetector_.options = options.jumps;
    jumpDetector_.findRuns(points_, sigma, runs_);
    const double threshold = std::max(options.splitDistance, options.noiseSigmas * sigma);
    parts_.clear();
    for (const PointRun& run : runs_)
        splitRun(run, threshold);
    assembly_.options = options.assembly;
    assembly_.assemble(points_, parts_, sigma, out);
}

}  // namespace toposlam::features
