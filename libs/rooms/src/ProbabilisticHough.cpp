#include <toposlam/rooms/ProbabilisticHough.h>

#include <opencv2/core.hpp>
#include <opencv2/core/hal/intrin.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdlib>

namespace toposlam::rooms {

namespace {

// The walks along a line step one pixel along its main axis and a 16.16 fixed-point fraction
// of a pixel across it.
constexpr int kShift = 16;

}  // namespace

void ProbabilisticHough::cellsOf(int x, int y) {
    // OpenCV's cvRound(x * cos + y * sin) in float, four angles at once (v_round rounds as
    // cvRound does: to nearest, ties to even).
    const cv::v_float32x4 fx = cv::v_setall_f32(static_cast<float>(x)),
                          fy = cv::v_setall_f32(static_cast<float>(y));
    int n = 0;
    for (; n + 4 <= angles_; n += 4) {
        const cv::v_int32x4 distance =
            cv::v_round(fx * cv::v_load(cosines_.data() + n) + fy * cv::v_load(sines_.data() + n));
        cv::v_store(cells_.data() + n, distance + cv::v_load(rowOffset_.data() + n));
    }
    for (; n < angles_; ++n) {
        const auto i = static_cast<std::size_t>(n);
        cells_[i] = rowOffset_[i] + cvRound(static_cast<float>(x) * cosines_[i] +
                                            static_cast<float>(y) * sines_[i]);
    }
}

bool ProbabilisticHough::takeLine(int x, int y, int n, int minLength, int maxGap,
                                  cv::Vec4i& segment) {
    // Along (a, b), the line's direction: one pixel per step along the axis it runs closer to.
    const float a = -sines_[static_cast<std::size_t>(n)], b = cosines_[static_cast<std::size_t>(n)];
    const bool alongX = std::fabs(a) > std::fabs(b);
    int x0 = x, y0 = y, dx0 = 0, dy0 = 0;
    if (alongX) {
        dx0 = a > 0 ? 1 : -1;
        dy0 = cvRound(b * (1 << kShift) / std::fabs(a));
        y0 = (y0 << kShift) + (1 << (kShift - 1));
    } else {
        dy0 = b > 0 ? 1 : -1;
        dx0 = cvRound(a * (1 << kShift) / std::fabs(b));
        x0 = (x0 << kShift) + (1 << (kShift - 1));
    }
    auto pixelAt = [&](int px, int py) {
        return alongX ? cv::Point(px, py >> kShift) : cv::Point(px >> kShift, py);
    };

    // Both ways from the pixel: the last set pixel before a gap wider than maxGap or the border.
    cv::Point ends[2];
    for (int k = 0; k < 2; ++k) {
        const int dx = k == 0 ? dx0 : -dx0, dy = k == 0 ? dy0 : -dy0;
        int gap = 0;
        for (int px = x0, py = y0;; px += dx, py += dy) {
            const cv::Point p = pixelAt(px, py);
            if (p.x < 0 || p.x >= width_ || p.y < 0 || p.y >= height_)
                break;
            if (maskAt(p) != 0) {
                gap = 0;
                ends[k] = p;
            } else if (++gap > maxGap) {
                break;
            }
        }
    }
    const bool isSegment = std::abs(ends[1].x - ends[0].x) >= minLength ||
                           std::abs(ends[1].y - ends[0].y) >= minLength;

    // The pixels between the ends leave the image; a segment's also take back their votes
    // (those of pixels yet to be drawn too: they will not vote, and the accumulator runs
    // below zero there, as OpenCV's does).
    for (int k = 0; k < 2; ++k) {
        const int dx = k == 0 ? dx0 : -dx0, dy = k == 0 ? dy0 : -dy0;
        for (int px = x0, py = y0;; px += dx, py += dy) {
            const cv::Point p = pixelAt(px, py);
            std::uint8_t& set = maskAt(p);
            if (set != 0) {
                if (isSegment) {
                    cellsOf(p.x, p.y);
                    std::int32_t* votes = votes_.data();
                    for (int m = 0; m < angles_; ++m)
                        --votes[cells_[static_cast<std::size_t>(m)]];
                }
                set = 0;
            }
            if (p == ends[k])
                break;
        }
    }
    segment = {ends[0].x, ends[0].y, ends[1].x, ends[1].y};
    return isSegment;
}

void ProbabilisticHough::find(const cv::Mat& image, const Parameters& p,
                              std::vector<cv::Vec4i>& lines) {
    CV_Assert(image.type() == CV_8UC1 && p.rho > 0 && p.theta > 0 && p.threshold > 0);
    lines.clear();
    width_ = image.cols;
    height_ = image.rows;
    // OpenCV's float steps and trigonometric table.
    const auto rho = static_cast<float>(p.rho), theta = static_cast<float>(p.theta);
    const float inverseRho = 1 / rho;
    angles_ = cvRound(CV_PI / theta);
    CV_Assert(angles_ > 0);
    const auto angles = static_cast<std::size_t>(angles_);
    cosines_.resize(angles);
    sines_.resize(angles);
    rowOffset_.resize(angles);
    cells_.resize(angles);
    // Per angle, the distances of the image's pixels lie between those of two of its corners
    // (x * cos + y * sin, rounded as computed, does not decrease or does not increase along
    // each axis), so only that range gets a row of the accumulator.
    std::size_t size = 0;
    for (std::size_t n = 0; n < angles; ++n) {
        cosines_[n] = static_cast<float>(std::cos(static_cast<double>(n) * theta) * inverseRho);
        sines_[n] = static_cast<float>(std::sin(static_cast<double>(n) * theta) * inverseRho);
        int lowest = INT_MAX, highest = INT_MIN;
        for (const int y : {0, std::max(0, height_ - 1)}) {
            for (const int x : {0, std::max(0, width_ - 1)}) {
                const int r = cvRound(static_cast<float>(x) * cosines_[n] +
                                      static_cast<float>(y) * sines_[n]);
                lowest = std::min(lowest, r);
                highest = std::max(highest, r);
            }
        }
        rowOffset_[n] = static_cast<int>(size) - lowest;
        size += static_cast<std::size_t>(highest - lowest + 1);
    }
    votes_.assign(size, 0);

    mask_.resize(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
    pixels_.clear();
    for (int y = 0; y < height_; ++y) {
        const std::uint8_t* row = image.ptr<std::uint8_t>(y);
        std::uint8_t* set =
            mask_.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width_);
        for (int x = 0; x < width_; ++x) {
            set[x] = row[x] != 0 ? 1 : 0;
            if (row[x] != 0)
                pixels_.emplace_back(x, y);
        }
    }

    const int minLength = cvRound(p.minLineLength), maxGap = cvRound(p.maxLineGap);
    cv::RNG random(static_cast<std::uint64_t>(-1));  // OpenCV's seed: its order of the pixels
    const cv::v_int32x4 noLine = cv::v_setall_s32(p.threshold - 1);
    for (auto count = static_cast<int>(pixels_.size()); count > 0; --count) {
        const auto pick = static_cast<std::size_t>(random.uniform(0, count));
        const cv::Point pixel = pixels_[pick];
        pixels_[pick] = pixels_[static_cast<std::size_t>(count - 1)];
        if (maskAt(pixel) == 0)
            continue;  // drawn with an earlier line
        // Its votes; then the strongest line, the first angle with the most votes.
        cellsOf(pixel.x, pixel.y);
        int* cells = cells_.data();
        std::int32_t* votes = votes_.data();
        for (int n = 0; n < angles_; ++n)
            cells[n] = ++votes[cells[n]];
        cv::v_int32x4 most4 = noLine;
        int n = 0;
        for (; n + 4 <= angles_; n += 4)
            most4 = cv::v_max(most4, cv::v_load(cells + n));
        int most = cv::v_reduce_max(most4);
        for (; n < angles_; ++n)
            most = std::max(most, cells[n]);
        if (most < p.threshold)
            continue;
        int strongest = 0;
        while (cells[strongest] != most)
            ++strongest;
        cv::Vec4i segment;
        if (takeLine(pixel.x, pixel.y, strongest, minLength, maxGap, segment))
            lines.push_back(segment);
    }
}

}  // namespace toposlam::rooms
