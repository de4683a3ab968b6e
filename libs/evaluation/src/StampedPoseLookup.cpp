#include <toposlam/evaluation/StampedPoseLookup.h>

#include <algorithm>
#include <cmath>

namespace toposlam::evaluation {

StampedPoseLookup::StampedPoseLookup(const io::Trajectory2D& trajectory, double tolerance)
    : tolerance_(tolerance) {
    byStamp_.reserve(trajectory.size());
    for (std::size_t i = 0; i < trajectory.size(); ++i)
        byStamp_.emplace_back(trajectory[i].stamp, i);
    std::sort(byStamp_.begin(), byStamp_.end());
}

std::optional<std::size_t> StampedPoseLookup::find(double stamp) const {
    // The nearest stamp is the first one >= stamp or the one before it.
    const auto after =
        std::lower_bound(byStamp_.begin(), byStamp_.end(), std::make_pair(stamp, std::size_t{0}));
    std::optional<std::size_t> best;
    double bestDistance = tolerance_;
    auto consider = [&](std::vector<std::pair<double, std::size_t>>::const_iterator it) {
        const double d = std::abs(it->first - stamp);
        if (d < bestDistance || (d == bestDistance && (!best || it->second < *best))) {
            bestDistance = d;
            best = it->second;
        }
    };
    if (after != byStamp_.begin())
        consider(after - 1);
    if (after != byStamp_.end())
        consider(after);
    return best;
}

}  // namespace toposlam::evaluation
