#include <toposlam/rooms/DoorSearchPaths.h>

#include "ChamferDistance.h"
#include "GridRay.h"

#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace toposlam::rooms {

std::vector<cv::Point> DoorSearchPaths::fromTrajectory(
    const FreeSpace& space, const std::vector<mrpt::math::TPose2D>& poses) {
    std::vector<cv::Point> cells;
    cv::Mat seen = cv::Mat::zeros(space.free.size(), CV_8U);
    const cv::Rect image(0, 0, space.free.cols, space.free.rows);
    auto visit = [&](const cv::Point& p) {
        if (!image.contains(p) || space.free.at<std::uint8_t>(p) == 0 ||
            seen.at<std::uint8_t>(p) != 0) {
            return;
        }
        seen.at<std::uint8_t>(p) = 1;
        cells.push_back(p);
    };
    for (std::size_t i = 0; i < poses.size(); ++i) {
        const cv::Point a = space.frame.toCell(poses[i].x, poses[i].y);
        if (i == 0) {
            visit(a);
            continue;
        }
        const cv::Point b = space.frame.toCell(poses[i - 1].x, poses[i - 1].y);
        // Walk from the previous pose to this one; LineIterator needs both ends inside.
        cv::Point pa = a, pb = b;
        if (!cv::clipLine(image, pb, pa))
            continue;
        cv::LineIterator it(pb, pa, 8);
        for (int k = 0; k < it.count; ++k, ++it)
            visit(it.pos());
    }
    return cells;
}

void Clearance::compute(const cv::Mat& free) {
    detail::chamferDistance5x5(free, distance_, rows_);
}

double Clearance::acrossRidge(const cv::Point& p) const {
    auto d = [&](int dx, int dy) {
        const int x = std::clamp(p.x + dx, 0, distance_.cols - 1);
        const int y = std::clamp(p.y + dy, 0, distance_.rows - 1);
        return static_cast<double>(distance_.at<float>(y, x));
    };
    const double centre = d(0, 0);
    const double xx = d(2, 0) - 2 * centre + d(-2, 0);
    const double yy = d(0, 2) - 2 * centre + d(0, -2);
    const double xy = 0.25 * (d(2, 2) - d(2, -2) - d(-2, 2) + d(-2, -2));
    // Eigenvector of the smaller eigenvalue of [[xx, xy], [xy, yy]].
    double a = 0.5 * std::atan2(2 * xy, xx - yy) + M_PI / 2;
    while (a >= M_PI)
        a -= M_PI;
    while (a < 0)
        a += M_PI;
    return a;
}

std::vector<double> Clearance::acrossRidge(const std::vector<cv::Point>& cells) const {
    std::vector<double> directions;
    directions.reserve(cells.size());
    for (const cv::Point& p : cells)
        directions.push_back(acrossRidge(p));
    return directions;
}

std::vector<cv::Point> DoorSearchPaths::fromMedialAxis(const FreeSpace& space,
                                                       const Clearance& clearance,
                                                       double minDoorWidth, double maxDoorWidth) {
    return std::move(fromMedialAxis(space, clearance, {{minDoorWidth, maxDoorWidth}}).front());
}

std::vector<std::vector<cv::Point>> DoorSearchPaths::fromMedialAxis(
    const FreeSpace& space, const Clearance& clearance,
    const std::vector<std::pair<double, double>>& widths) {
    const double res = space.frame.resolution;
    // Per range, the clearance of the middle of such an opening, a cell either way.
    std::vector<std::pair<float, float>> ranges;
    float lowest = std::numeric_limits<float>::infinity(), highest = -lowest;
    for (const auto& [minWidth, maxWidth] : widths) {
        const float lo = static_cast<float>(0.5 * detail::toCells(minWidth, res) - 1.0);
        const float hi = static_cast<float>(0.5 * detail::toCells(maxWidth, res) + 1.0);
        ranges.emplace_back(lo, hi);
        lowest = std::min(lowest, lo);
        highest = std::max(highest, hi);
    }
    const cv::Mat& dist = clearance.distances();
    std::vector<std::vector<cv::Point>> cells(ranges.size());
    auto keep = [&](float d, int c, int r) {
        for (std::size_t k = 0; k < ranges.size(); ++k) {
            if (d >= ranges[k].first && d <= ranges[k].second)
                cells[k].emplace_back(c, r);
        }
    };
    // Local maximum across an axis: not below either neighbour, above at least one.
    auto ridge = [](float d, float a, float b) { return d >= a && d >= b && (d > a || d > b); };
    using cv::v_float32x4;
    auto ridge4 = [](const v_float32x4& d, const v_float32x4& a, const v_float32x4& b) {
        return (d >= a) & (d >= b) & ((d > a) | (d > b));
    };
    const v_float32x4 lowest4 = cv::v_setall_f32(lowest), highest4 = cv::v_setall_f32(highest);
    for (int r = 1; r + 1 < dist.rows; ++r) {
        const float* up = dist.ptr<float>(r - 1);
        const float* row = dist.ptr<float>(r);
        const float* down = dist.ptr<float>(r + 1);
        int c = 1;
        // Four cells at a time: most are walls (clearance 0) or far from any wall, and the four
        // ridge tests are cheaper side by side than their branches one cell at a time.
        for (; c + 5 <= dist.cols; c += 4) {
            const v_float32x4 d = cv::v_load(row + c);
            const v_float32x4 inRange = (d >= lowest4) & (d <= highest4);
            if (!cv::v_check_any(inRange))
                continue;
            const v_float32x4 isRidge =
                ridge4(d, cv::v_load(row + c - 1), cv::v_load(row + c + 1)) |
                ridge4(d, cv::v_load(up + c), cv::v_load(down + c)) |
                ridge4(d, cv::v_load(up + c - 1), cv::v_load(down + c + 1)) |
                ridge4(d, cv::v_load(up + c + 1), cv::v_load(down + c - 1));
            const int bits = cv::v_signmask(inRange & isRidge);
            for (int lane = 0; lane < 4; ++lane) {
                if ((bits >> lane) & 1)
                    keep(row[c + lane], c + lane, r);
            }
        }
        for (; c + 1 < dist.cols; ++c) {
            const float d = row[c];
            if (d < lowest || d > highest)
                continue;
            if (ridge(d, row[c - 1], row[c + 1]) || ridge(d, up[c], down[c]) ||
                ridge(d, up[c - 1], down[c + 1]) || ridge(d, up[c + 1], down[c - 1])) {
                keep(d, c, r);
            }
        }
    }
    return cells;
}

}  // namespace toposlam::rooms
