#pragma once
// Summary of a set of non-negative error values: how many, mean, standard deviation, maximum.
#include <cstddef>
#include <vector>

namespace toposlam::evaluation {

struct ErrorStatistics {
    std::size_t count = 0;
    double mean = 0;
    /// Sample standard deviation (divides by count - 1, as Cartographer's relation metric and
    /// most published tables do); 0 when count < 2.
    double std = 0;
    double max = 0;
    /// sqrt(mean of the squared values).
    double rms = 0;
};

/// Statistics of `values` (all zero when it is empty). Two-pass, so large means do not cost
/// precision in the standard deviation.
ErrorStatistics summarizeErrors(const std::vector<double>& values);

}  // namespace toposlam::evaluation
