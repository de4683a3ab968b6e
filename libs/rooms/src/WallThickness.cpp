#include <toposlam/rooms/WallThickness.h>

#include "GridRay.h"

#include <opencv2/core/hal/intrin.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace toposlam::rooms {

void WallThickness::measure(const FreeSpace& space, const Clearance& clearance,
                            double maxThickness) {
    const cv::Mat& free = space.free;
    // On SLAM grids a run must cross a cell the laser hit: one through unknown cells only (a
    // streak between the beams that saw a room through its door, the ragged edge of the mapped
    // space) is no wall. Such one-cell runs outnumbered the walls' own on a long corridor whose
    // offices were seen only through their doors, and every wall end there failed the test.
    const cv::Mat& unknown = space.unknown;
    const cv::Mat& d = clearance.distances();
    const int cap =
        static_cast<int>(std::ceil(detail::toCells(maxThickness, space.frame.resolution))) + 2;
    stepCells_ = std::max(1.0, detail::toCells(kThicknessStep, space.frame.resolution));
    counts_.assign(static_cast<std::size_t>(std::lround(cap / stepCells_)) + 2, 0.0);
    // The obstacle run behind the free cell (c, r) next to an obstacle, if it is a wall's.
    auto measureAt = [&](int c, int r) {
        const float* dist = d.ptr<float>(r);
        // Into the obstacle: against the clearance gradient (central differences).
        const double gx = dist[c + 1] - dist[c - 1];
        const double gy = d.at<float>(r + 1, c) - d.at<float>(r - 1, c);
        const double norm = std::hypot(gx, gy);
        if (norm < 1e-6)
            return;
        cv::Point hit;
        bool occupied = unknown.empty();  // drawn maps: every non-free cell is occupied
        const bool found = detail::withMaskReader(free, {c, r}, cap + 1, [&](const auto& isFree) {
            return detail::walkRay(
                {c, r}, -gx / norm, -gy / norm, cap,
                [&](int x, int y) {
                    if (isFree(x, y))
                        return true;
                    occupied = occupied || !detail::isSet(unknown, x, y);
                    return false;
                },
                hit);
        });
        if (!found || !occupied)
            return;
        const double run = detail::cellDistance(hit.x - c, hit.y - r) - 1.0;  // obstacle cells
        if (run >= 0.5)  // shorter: a diagonal gap, not an obstacle
            counts_[static_cast<std::size_t>(std::lround(run / stepCells_))] += 1.0;
    };
    // Free cells next to an obstacle (clearance 1: a 4-neighbour is not free). The clearance
    // of the other free cells is above 1, of obstacles 0: four cells are tested at once, as
    // few of them are wall faces.
    const cv::v_float32x4 zero = cv::v_setzero_f32(), one = cv::v_setall_f32(1.0f);
    for (int r = 1; r + 1 < free.rows; ++r) {
        const auto* row = free.ptr<std::uint8_t>(r);
        const float* dist = d.ptr<float>(r);
        auto isFace = [&](int c) { return row[c] != 0 && dist[c] <= 1.0f; };
        int c = 1;
        for (; c + 5 <= free.cols; c += 4) {
            const cv::v_float32x4 d4 = cv::v_load(dist + c);
            if (!cv::v_check_any((d4 > zero) & (d4 <= one)))
                continue;
            for (int k = c; k < c + 4; ++k) {
                if (isFace(k))
                    measureAt(k, r);
            }
        }
        for (; c + 1 < free.cols; ++c) {
            if (isFace(c))
                measureAt(c, r);
        }
    }
    mode_ = 0;
    double best = 0;
    for (int k = 1; k + 1 < static_cast<int>(counts_.size()); ++k) {
        if (smoothed(k) > best) {
            best = smoothed(k);
            mode_ = k;
        }
    }
}

double WallThickness::smoothed(int k) const {  // k in steps
    auto at = [&](int i) {
        return i >= 0 && i < static_cast<int>(counts_.size()) ? counts_[static_cast<std::size_t>(i)]
                                                              : 0.0;
    };
    return at(k - 1) + 2 * at(k) + at(k + 1);
}

bool WallThickness::isWallThickness(double cells, double minShare) const {
    if (mode_ == 0)
        return true;
    const int k = static_cast<int>(std::lround(cells / stepCells_));
    if (std::abs(k - mode_) <= 1)
        return true;
    return smoothed(k) >= minShare * smoothed(mode_);
}

}  // namespace toposlam::rooms
