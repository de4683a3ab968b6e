#include <toposlam/io/CarmenTimestamps.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace toposlam::io {

std::vector<double> carmenStampCandidates(std::string_view printed) {
    double asPrinted = 0;
    const auto res = std::from_chars(printed.data(), printed.data() + printed.size(), asPrinted);
    if (res.ec != std::errc() || res.ptr != printed.data() + printed.size() ||
        !std::isfinite(asPrinted)) {
        return {};
    }
    std::vector<double> candidates{asPrinted};
    const auto dot = printed.find('.');
    if (dot == std::string_view::npos || printed.front() == '-')
        return candidates;
    double seconds = 0;
    if (dot > 0)
        std::from_chars(printed.data(), printed.data() + dot, seconds);
    std::string_view digits = printed.substr(dot + 1);
    if (digits.empty() || digits.front() == '0')
        return candidates;  // unpadded never starts with 0
    while (true) {
        if (digits.size() < 6) {
            unsigned long micros = 0;
            std::from_chars(digits.data(), digits.data() + digits.size(), micros);
            candidates.push_back(seconds + static_cast<double>(micros) * 1e-6);
        }
        if (digits.size() <= 1 || digits.back() != '0')
            break;
        digits.remove_suffix(1);
    }
    return candidates;
}

CarmenTimestampRepair repairCarmenTimestamps(const std::vector<std::string_view>& printed) {
    constexpr double kStepBackCost = 1000.0;      // a time that does not increase
    constexpr double kReinterpretCost = 1.0;      // a stamp read as unpadded microseconds
    constexpr double kPerDroppedZeroCost = 1e-3;  // prefer the shortest reinterpretation
    const std::size_t n = printed.size();
    CarmenTimestampRepair out;
    out.times.resize(n);
    if (n == 0)
        return out;

    // candidates[i][k], their own cost, and the DP tables (best total cost, argmin parent).
    std::vector<std::vector<double>> candidates(n);
    for (std::size_t i = 0; i < n; ++i) {
        candidates[i] = carmenStampCandidates(printed[i]);
        if (candidates[i].empty()) {
            candidates[i] = {i > 0 ? candidates[i - 1].front() : 0.0};
        }
    }
    const auto ownCost = [](std::size_t k) {
        return k == 0 ? 0.0 : kReinterpretCost + kPerDroppedZeroCost * static_cast<double>(k);
    };
    std::vector<std::vector<double>> cost(n);
    std::vector<std::vector<std::size_t>> parent(n);
    cost[0].resize(candidates[0].size());
    for (std::size_t k = 0; k < candidates[0].size(); ++k)
        cost[0][k] = ownCost(k);
    for (std::size_t i = 1; i < n; ++i) {
        const auto& prev = candidates[i - 1];
        cost[i].resize(candidates[i].size());
        parent[i].resize(candidates[i].size());
        for (std::size_t k = 0; k < candidates[i].size(); ++k) {
            double best = std::numeric_limits<double>::infinity();
            std::size_t arg = 0;
            for (std::size_t j = 0; j < prev.size(); ++j) {
                const double c =
                    cost[i - 1][j] + (candidates[i][k] <= prev[j] ? kStepBackCost : 0.0);
                if (c < best) {
                    best = c;
                    arg = j;
                }
            }
            cost[i][k] = best + ownCost(k);
            parent[i][k] = arg;
        }
    }
    std::size_t k = static_cast<std::size_t>(
        std::min_element(cost[n - 1].begin(), cost[n - 1].end()) - cost[n - 1].begin());
    for (std::size_t i = n; i-- > 0;) {
        out.times[i] = candidates[i][k];
        if (k != 0)
            ++out.reinterpreted;
        if (i > 0)
            k = parent[i][k];
    }
    for (std::size_t i = 1; i < n; ++i) {
        if (out.times[i] <= out.times[i - 1]) {
            out.times[i] = out.times[i - 1] + 1e-6;
            ++out.forced;
        }
    }
    return out;
}

}  // namespace toposlam::io
