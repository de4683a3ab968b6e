#include "ChamferDistance.h"

#include <opencv2/core/hal/intrin.hpp>

#include <algorithm>
#include <climits>
#include <cstdint>

namespace toposlam::rooms::detail {

namespace {

// OpenCV's weights for DIST_L2 with DIST_MASK_5, in its fixed point (distransform.cpp).
constexpr int kShift = 16;
const int kStep = cvRound(1.0f * (1 << kShift));       // horizontal and vertical neighbours
const int kDiagonal = cvRound(1.4f * (1 << kShift));   // diagonal neighbours
const int kKnight = cvRound(2.1969f * (1 << kShift));  // (1, 2) and (2, 1) offsets
// OpenCV's cap on distances (8192 px); also the distance beyond the image here (OpenCV starts
// from INT_MAX there, unsigned, which gives the same capped distances).
constexpr int kFar = INT_MAX >> 2;

// min over the mask's terms from rows `near` (one row away) and `next` (two rows away) at column
// c; the mask is symmetric, so the same for the rows above (forward) and below (backward).
inline int fromOtherRows(const int* near, const int* next, int c) {
    int m = std::min(next[c - 1], next[c + 1]) + kKnight;
    m = std::min(m, std::min(near[c - 2], near[c + 2]) + kKnight);
    m = std::min(m, std::min(near[c - 1], near[c + 1]) + kDiagonal);
    return std::min(m, near[c] + kStep);
}

using cv::v_int32x4;

// Beyond any distance plus two steps, and still that plus two steps without overflow: what
// lies outside a block of four when its own cells are combined.
constexpr int kBeyond = INT_MAX >> 1;

// value = min(cell, value + kStep) walked over a block of four cells `v`, towards its last lane
// (Forward) or its first: the block's own cells first (each with the one, then the two, before
// it), then `carry`, the value before the block, which becomes the value at its end. The blocks
// wait on one another for one add and one min each. Integer minima of sums: the same values as
// cell by cell.
template <bool Forward>
v_int32x4 runningMinimum4(v_int32x4 v, int& carry) {
    const v_int32x4 beyond = cv::v_setall_s32(kBeyond);
    int end = 0;
    if constexpr (Forward) {
        v = cv::v_min(v, cv::v_rotate_left<1>(v, beyond) + cv::v_setall_s32(kStep));
        v = cv::v_min(v, cv::v_rotate_left<2>(v, beyond) + cv::v_setall_s32(2 * kStep));
        end = cv::v_extract_n<3>(v);
        v = cv::v_min(v,
                      cv::v_setall_s32(carry) + v_int32x4(kStep, 2 * kStep, 3 * kStep, 4 * kStep));
    } else {
        v = cv::v_min(v, cv::v_rotate_right<1>(v, beyond) + cv::v_setall_s32(kStep));
        v = cv::v_min(v, cv::v_rotate_right<2>(v, beyond) + cv::v_setall_s32(2 * kStep));
        end = cv::v_extract_n<0>(v);
        v = cv::v_min(v,
                      cv::v_setall_s32(carry) + v_int32x4(4 * kStep, 3 * kStep, 2 * kStep, kStep));
    }
    carry = std::min(end, carry + 4 * kStep);
    return v;
}

}  // namespace

void chamferDistance5x5(const cv::Mat& free, cv::Mat& out, std::vector<int>& rowsScratch) {
    CV_Assert(free.type() == CV_8U);
    const int rows = free.rows, cols = free.cols;
    out.create(rows, cols, CV_32F);
    // Three rows of cols + 4 (two far columns each side); row r in slot (r + 3) % 3, so rows -2
    // and -1 (rows + 1 and rows, backward) are far slots until written.
    const std::size_t width = static_cast<std::size_t>(cols) + 4;
    rowsScratch.assign(3 * width, kFar);
    auto slot = [&](int r) {
        return rowsScratch.data() + static_cast<std::size_t>((r + 3) % 3) * width + 2;
    };
    const v_int32x4 step = cv::v_setall_s32(kStep), diagonal = cv::v_setall_s32(kDiagonal),
                    knight = cv::v_setall_s32(kKnight), zero = cv::v_setzero_s32();
    const v_int32x4 far = cv::v_setall_s32(kFar);
    auto fromOtherRows4 = [&](const int* near, const int* next, int c) {
        v_int32x4 m = cv::v_min(cv::v_load(next + c - 1), cv::v_load(next + c + 1)) + knight;
        m = cv::v_min(m, cv::v_min(cv::v_load(near + c - 2), cv::v_load(near + c + 2)) + knight);
        m = cv::v_min(m, cv::v_min(cv::v_load(near + c - 1), cv::v_load(near + c + 1)) + diagonal);
        return cv::v_min(m, cv::v_load(near + c) + step);
    };

    // Forward pass, top to bottom: the terms from above, then the one from the left.
    for (int r = 0; r < rows; ++r) {
        const std::uint8_t* isFree = free.ptr<std::uint8_t>(r);
        int* t = slot(r);
        const int* above = slot(r - 1);
        const int* above2 = slot(r - 2);
        int c = 0;
        for (; c + 4 <= cols; c += 4) {
            // (Not v_load_expand_q: OpenCV's SSE version reads the four bytes as an int, which
            // need not be aligned.)
            const v_int32x4 f(isFree[c], isFree[c + 1], isFree[c + 2], isFree[c + 3]);
            cv::v_store(t + c, cv::v_select(f == zero, zero, fromOtherRows4(above, above2, c)));
        }
        for (; c < cols; ++c)
            t[c] = isFree[c] ? fromOtherRows(above, above2, c) : 0;
        // left = min(t[c], left + kStep) from c = 0 on, four cells at a time.
        int* pass = out.ptr<int>(r);  // the integer distances wait in `out`
        int left = kFar;
        for (c = 0; c + 4 <= cols; c += 4) {
            const v_int32x4 v = runningMinimum4<true>(cv::v_load(t + c), left);
            cv::v_store(t + c, v);
            cv::v_store(pass + c, v);
        }
        for (; c < cols; ++c) {
            left = std::min(t[c], left + kStep);
            t[c] = pass[c] = left;
        }
    }

    // Backward pass, bottom to top: the terms from below, then the one from the right.
    std::fill(rowsScratch.begin(), rowsScratch.end(), kFar);
    const float scale = 1.f / (1 << kShift);
    const cv::v_float32x4 scale4 = cv::v_setall_f32(scale);
    for (int r = rows - 1; r >= 0; --r) {
        int* t = slot(r);
        const int* below = slot(r + 1);
        const int* below2 = slot(r + 2);
        const int* pass = out.ptr<int>(r);
        int c = 0;
        for (; c + 4 <= cols; c += 4)
            cv::v_store(t + c, cv::v_min(cv::v_load(pass + c), fromOtherRows4(below, below2, c)));
        for (; c < cols; ++c)
            t[c] = std::min(pass[c], fromOtherRows(below, below2, c));
        // right = min(t[c], right + kStep) from the last cell back, as forward: the cells past
        // the last whole block of four one by one, then the blocks.
        float* distance = out.ptr<float>(r);
        const int blocks = cols - cols % 4;
        int right = kFar;
        for (c = cols - 1; c >= blocks; --c) {
            right = std::min(t[c], right + kStep);
            t[c] = right;
            distance[c] = static_cast<float>(std::min(right, kFar)) * scale;  // as OpenCV caps
        }
        for (c = blocks - 4; c >= 0; c -= 4) {
            const v_int32x4 v = runningMinimum4<false>(cv::v_load(t + c), right);
            cv::v_store(t + c, v);
            cv::v_store(distance + c, cv::v_cvt_f32(cv::v_min(v, far)) * scale4);
        }
    }
}

}  // namespace toposlam::rooms::detail
