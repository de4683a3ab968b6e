#include <toposlam/simulation/TourOrder.h>

#include <algorithm>
#include <limits>

namespace toposlam::simulation {

double tourCost(const std::vector<std::vector<double>>& cost, const std::vector<std::size_t>& order,
                bool closed) {
    double sum = 0;
    for (std::size_t i = 1; i < order.size(); ++i)
        sum += cost[order[i - 1]][order[i]];
    if (closed && order.size() > 1)
        sum += cost[order.back()][order.front()];
    return sum;
}

std::vector<std::size_t> orderVisits(const std::vector<std::vector<double>>& rawCost, bool closed) {
    const std::size_t n = rawCost.size();
    if (n == 0)
        return {};
    std::vector<std::vector<double>> c(n, std::vector<double>(n, 0.0));
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j)
            c[i][j] = 0.5 * (rawCost[i][j] + rawCost[j][i]);
    }

    // Nearest neighbour from place 0.
    std::vector<std::size_t> order{0};
    std::vector<bool> used(n, false);
    used[0] = true;
    for (std::size_t k = 1; k < n; ++k) {
        std::size_t best = n;
        for (std::size_t j = 0; j < n; ++j) {
            if (!used[j] && (best == n || c[order.back()][j] < c[order.back()][best]))
                best = j;
        }
        used[best] = true;
        order.push_back(best);
    }

    // 2-opt: reverse order[i..j] when that shortens the tour; place 0 stays first.
    const auto edge = [&](std::size_t a, std::size_t b) {
        if (b >= order.size())
            return closed ? c[order[a]][order[0]] : 0.0;
        return c[order[a]][order[b]];
    };
    for (bool improved = true; improved;) {
        improved = false;
        for (std::size_t i = 1; i < order.size(); ++i) {
            for (std::size_t j = i + 1; j < order.size(); ++j) {
                const double before = edge(i - 1, i) + edge(j, j + 1);
                const double after =
                    c[order[i - 1]][order[j]] + (j + 1 < order.size()
                                                     ? c[order[i]][order[j + 1]]
                                                     : (closed ? c[order[i]][order[0]] : 0.0));
                if (after < before - 1e-9) {
                    std::reverse(order.begin() + static_cast<long>(i),
                                 order.begin() + static_cast<long>(j) + 1);
                    improved = true;
                }
            }
        }
    }
    return order;
}

}  // namespace toposlam::simulation
