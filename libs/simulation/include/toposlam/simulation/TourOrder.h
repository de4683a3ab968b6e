#pragma once
// The order in which a tour visits its places: a travelling-salesman heuristic (nearest
// neighbour, then 2-opt until no reversal of a sub-sequence shortens the tour). Tours here have
// ten to a hundred places, where this is within a few percent of optimal.
#include <cstddef>
#include <vector>

namespace toposlam::simulation {

/// Visiting order of places 0..n-1, starting at place 0, given the travel cost between every
/// pair (`cost[i][j]`, made symmetric by averaging; +infinity = unreachable, such places must be
/// removed beforehand). `closed`: the tour returns to place 0 at the end, which counts in the
/// cost. Returns the place indices, beginning with 0 (without the return).
std::vector<std::size_t> orderVisits(const std::vector<std::vector<double>>& cost, bool closed);

/// Cost of visiting `order` (and returning to its first place when `closed`).
double tourCost(const std::vector<std::vector<double>>& cost, const std::vector<std::size_t>& order,
                bool closed);

}  // namespace toposlam::simulation
