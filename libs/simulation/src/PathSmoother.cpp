#include <toposlam/simulation/PathSmoother.h>

#include <cmath>

namespace toposlam::simulation {

using mrpt::math::TPoint2D;

std::vector<TPoint2D> resamplePolyline(const std::vector<TPoint2D>& path, double spacing) {
    if (path.size() < 2)
        return path;
    std::vector<TPoint2D> out{path.front()};
    double carried = 0;  // arc length since the last output point
    for (std::size_t i = 1; i < path.size(); ++i) {
        const TPoint2D a = path[i - 1], b = path[i];
        const double len = std::hypot(b.x - a.x, b.y - a.y);
        double s = spacing - carried;  // position of the next output point along this segment
        while (s <= len) {
            const double f = s / len;
            out.push_back({a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)});
            s += spacing;
        }
        carried = len - (s - spacing);
    }
    // The last point: replace a sample that fell almost on it, otherwise append it.
    const TPoint2D& end = path.back();
    if (std::hypot(out.back().x - end.x, out.back().y - end.y) < 0.5 * spacing && out.size() > 1) {
        out.back() = end;
    } else {
        out.push_back(end);
    }
    return out;
}

std::vector<TPoint2D> smoothPath(const std::vector<TPoint2D>& path, const GridPathPlanner& planner,
                                 double sigma, double spacing) {
    std::vector<TPoint2D> pts = resamplePolyline(path, spacing);
    const int n = static_cast<int>(pts.size());
    if (n < 3 || sigma <= 0)
        return pts;

    const int half = static_cast<int>(std::ceil(3 * sigma / spacing));
    std::vector<double> kernel(static_cast<std::size_t>(2 * half + 1));
    for (int k = -half; k <= half; ++k) {
        const double u = k * spacing / sigma;
        kernel[static_cast<std::size_t>(k + half)] = std::exp(-0.5 * u * u);
    }
    // Point reflection through the ends: p[-k] = 2 p[0] - p[k], p[n-1+k] = 2 p[n-1] - p[n-1-k].
    const auto at = [&](int i) -> TPoint2D {
        if (i < 0) {
            const TPoint2D& q = pts[static_cast<std::size_t>(std::min(-i, n - 1))];
            return {2 * pts[0].x - q.x, 2 * pts[0].y - q.y};
        }
        if (i >= n) {
            const TPoint2D& q = pts[static_cast<std::size_t>(std::max(2 * (n - 1) - i, 0))];
            return {2 * pts[static_cast<std::size_t>(n - 1)].x - q.x,
                    2 * pts[static_cast<std::size_t>(n - 1)].y - q.y};
        }
        return pts[static_cast<std::size_t>(i)];
    };
    std::vector<TPoint2D> smooth(pts.size());
    smooth.front() = pts.front();
    smooth.back() = pts.back();
    for (int i = 1; i + 1 < n; ++i) {
        double sx = 0, sy = 0, sw = 0;
        for (int k = -half; k <= half; ++k) {
            const double w = kernel[static_cast<std::size_t>(k + half)];
            const TPoint2D q = at(i + k);
            sx += w * q.x;
            sy += w * q.y;
            sw += w;
        }
        TPoint2D s{sx / sw, sy / sw};
        const TPoint2D& o = pts[static_cast<std::size_t>(i)];
        // Pull back towards the original point until the robot fits there.
        for (double f = 0.5; !planner.traversable(s) && f > 1e-3; f *= 0.5) {
            s = {o.x + f * (s.x - o.x), o.y + f * (s.y - o.y)};
        }
        if (!planner.traversable(s))
            s = o;
        smooth[static_cast<std::size_t>(i)] = s;
    }
    return resamplePolyline(smooth, spacing);
}

}  // namespace toposlam::simulation
