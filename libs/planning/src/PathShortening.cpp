#include <toposlam/planning/PathShortening.h>

#include <algorithm>
#include <cmath>

namespace toposlam::planning {

using mrpt::math::TPoint2D;

std::vector<TPoint2D> shortenPath(const TraversabilityGrid& grid, const std::vector<TPoint2D>& path,
                                  double spacing) {
    if (path.size() < 3)
        return path;
    std::vector<TPoint2D> dense{path.front()};
    for (std::size_t i = 1; i < path.size(); ++i) {
        const TPoint2D& a = path[i - 1];
        const TPoint2D& b = path[i];
        const int pieces =
            std::max(1, static_cast<int>(std::ceil(std::hypot(b.x - a.x, b.y - a.y) / spacing)));
        for (int k = 1; k <= pieces; ++k) {
            const double t = static_cast<double>(k) / pieces;
            dense.emplace_back(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
        }
    }
    std::vector<TPoint2D> taut{dense.front()};
    std::size_t i = 0;
    while (i + 1 < dense.size()) {
        std::size_t j = dense.size() - 1;
        while (j > i + 1 && !grid.isSegmentTraversable(dense[i], dense[j]))
            --j;
        taut.push_back(dense[j]);
        i = j;
    }
    return taut;
}

}  // namespace toposlam::planning
