#include <toposlam/mapping/ForegroundObjects.h>

#include <algorithm>
#include <cmath>

namespace toposlam::mapping {

namespace {
double distance(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b) {
    return std::hypot(a.x - b.x, a.y - b.y);
}
}  // namespace

std::size_t ForegroundObjects::remove(const matching::PolarScan& scan,
                                      const ForegroundObjectOptions& options,
                                      matching::PolarScan& out) {
    const std::size_t n = scan.size();
    // A reading beside an object hides nothing behind it when it is invalid (no return) or
    // lies clearly farther than the object's end next to it.
    const auto behind = [&](long beside, std::size_t end) {
        return beside < 0 || !scan.valid(std::size_t(beside)) ||
               scan.range(std::size_t(beside)) > scan.range(end) + options.inFront;
    };
    std::size_t removed = 0;
    for (std::size_t first = 0; first < n;) {
        if (!scan.valid(first)) {
            ++first;
            continue;
        }
        std::size_t last = first;
        double nearest = scan.range(first);
        while (last + 1 < n && scan.valid(last + 1) &&
               distance(scan.point(last), scan.point(last + 1)) <= options.breakDistance) {
            ++last;
            nearest = std::min(nearest, scan.range(last));
        }
        const bool foreground = nearest <= options.maxRange &&
                                distance(scan.point(first), scan.point(last)) <= options.maxWidth &&
                                behind(scan.neighbour(long(first), -1), first) &&
                                behind(scan.neighbour(long(last), 1), last);
        if (foreground) {
            if (removed == 0) {  // the first one found: copy the scan
                ranges_.resize(n);
                valid_.resize(n);
                for (std::size_t b = 0; b < n; ++b) {
                    ranges_[b] = float(scan.range(b));
                    valid_[b] = scan.valid(b);
                }
            }
            std::fill(valid_.begin() + long(first), valid_.begin() + long(last) + 1, char(0));
            removed += last - first + 1;
        }
        first = last + 1;
    }
    if (removed > 0)
        out.assign(scan.firstBearing(), scan.bearingStep(), ranges_, valid_, scan.maxRange());
    return removed;
}

}  // namespace toposlam::mapping
