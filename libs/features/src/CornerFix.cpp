#include <toposlam/features/CornerFix.h>

#include <cmath>
#include <limits>

namespace toposlam::features {

void fixCorners(const SlopeDifference& sd, std::vector<LinePart>& parts) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
        LinePart &first = parts[i], &second = parts[i + 1];
        if (!first.cornerAfter || first.end != first.joint || second.begin != first.joint) {
            continue;
        }
        const std::size_t q = first.joint;
        if (!sd.defined(q))
            continue;
        const double here = sd.value(q);
        const double toPrev = q > 0 && sd.defined(q - 1) ? std::abs(here - sd.value(q - 1)) : inf;
        const double toNext = q + 1 < sd.baseline.size() && sd.defined(q + 1)
                                  ? std::abs(here - sd.value(q + 1))
                                  : inf;
        if (toPrev == inf && toNext == inf)
            continue;
        if (toPrev < toNext) {
            if (first.end > first.begin)
                --first.end;
        } else {
            if (second.begin < second.end)
                ++second.begin;
        }
    }
}

}  // namespace toposlam::features
