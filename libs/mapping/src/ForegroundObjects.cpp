#include <toposlam/mapping/ForegroundObjects.h>

#include <algorithm>
#include <cmath>

namespace toposlam::mapping {

namespace {
double squaredDistance(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b) {
    return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
}
}  // namespace

template <typename Found>
void ForegroundObjects::forEachObject(const matching::PolarScan& scan,
                                      const ForegroundObjectOptions& options, Found&& found) {
    const std::size_t n = scan.size();
    // A reading beside an object hides nothing behind it when it is invalid (no return) or
    // lies clearly farther than the object's end next to it.
    const auto behind = [&](long beside, std::size_t end) {
        return beside < 0 || !scan.valid(std::size_t(beside)) ||
               scan.range(std::size_t(beside)) > scan.range(end) + options.inFront;
    };
    const double breakSquared = options.breakDistance * options.breakDistance;
    const double widthSquared = options.maxWidth * options.maxWidth;
    for (std::size_t first = 0; first < n;) {
        if (!scan.valid(first)) {
            ++first;
            continue;
        }
        std::size_t last = first;
        double nearest = scan.range(first);
        while (last + 1 < n && scan.valid(last + 1) &&
               squaredDistance(scan.point(last), scan.point(last + 1)) <= breakSquared) {
            ++last;
            nearest = std::min(nearest, scan.range(last));
        }
        const bool foreground =
            nearest <= options.maxRange &&
            squaredDistance(scan.point(first), scan.point(last)) <= widthSquared &&
            behind(scan.neighbour(long(first), -1), first) &&
            behind(scan.neighbour(long(last), 1), last);
        if (foreground && !found(first, last))
            return;
        first = last + 1;
    }
}

bool ForegroundObjects::any(const matching::PolarScan& scan,
                            const ForegroundObjectOptions& options) {
    bool seen = false;
    forEachObject(scan, options, [&](std::size_t, std::size_t) {
        seen = true;
        return false;  // one is enough
    });
    return seen;
}

std::size_t ForegroundObjects::remove(const matching::PolarScan& scan,
                                      const ForegroundObjectOptions& options,
                                      matching::PolarScan& out) {
    const std::size_t n = scan.size();
    std::size_t removed = 0;
    forEachObject(scan, options, [&](std::size_t first, std::size_t last) {
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
        return true;
    });
    if (removed > 0)
        out.assign(scan.firstBearing(), scan.bearingStep(), ranges_, valid_, scan.maxRange());
    return removed;
}

}  // namespace toposlam::mapping
