#include <toposlam/rooms/MainDirectionVoter.h>

#include <algorithm>
#include <cmath>

namespace toposlam::rooms {

namespace {

// Undirected angles live on a circle of circumference pi: distance between two of them.
double undirectedDistance(double a, double b) {
    const double d = std::fmod(std::abs(a - b), M_PI);
    return std::min(d, M_PI - d);
}

}  // namespace

MainDirections MainDirectionVoter::vote(const std::vector<LineSegment>& lines) const {
    MainDirections out;
    const int bins =
        std::max(2, static_cast<int>(std::lround(180.0 / (2.0 * options_.maxAngleDeg))));
    out.binWidth = M_PI / bins;
    out.votes.assign(static_cast<std::size_t>(bins), 0.0);
    // Per bin, the length-weighted mean of the doubled angle (doubling makes 0 and pi agree).
    std::vector<double> sumCos(static_cast<std::size_t>(bins), 0.0);
    std::vector<double> sumSin(static_cast<std::size_t>(bins), 0.0);
    for (const LineSegment& l : lines) {
        const double a = l.direction();
        const int k = static_cast<int>(std::floor(a / out.binWidth + 0.5)) % bins;
        const double w = l.length();
        out.votes[static_cast<std::size_t>(k)] += w;
        sumCos[static_cast<std::size_t>(k)] += w * std::cos(2 * a);
        sumSin[static_cast<std::size_t>(k)] += w * std::sin(2 * a);
    }
    auto binDirection = [&](std::size_t k) {
        double a = 0.5 * std::atan2(sumSin[k], sumCos[k]);
        return a < 0 ? a + M_PI : a;
    };
    const auto best = static_cast<std::size_t>(
        std::max_element(out.votes.begin(), out.votes.end()) - out.votes.begin());
    if (out.votes[best] <= 0)
        return out;                 // no segment: image axes
    out.phi1 = binDirection(best);  // eq. 8
    double bestOffset = 1e9;        // eq. 9: | |phi_i - phi1| - pi/2 | minimal
    for (std::size_t k = 0; k < out.votes.size(); ++k) {
        if (k == best || out.votes[k] <= 0)
            continue;
        const double offset = std::abs(undirectedDistance(binDirection(k), out.phi1) - M_PI / 2);
        if (offset < bestOffset) {
            bestOffset = offset;
            out.phi2 = binDirection(k);
        }
    }
    if (bestOffset == 1e9)
        out.phi2 = std::fmod(out.phi1 + M_PI / 2, M_PI);
    return out;
}

}  // namespace toposlam::rooms
