#pragma once
// Summary of a set of non-negative error values: how many, mean, standard deviation, maximum.
#include <cstddef>
#include <string>
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

// How the tables of toposlam-eval-slam and toposlam-bench-slam print errors.
/// `value` with `decimals` digits after the point.
std::string formatFixed(double value, int decimals);
/// Decimals that show `reference` with 4 significant digits (0 to 8).
int significantDecimals(double reference);
/// "mean ± std" with `decimals` digits after the point.
std::string formatMeanStd(const ErrorStatistics& s, int decimals);
/// "mean ± std" with 4 significant digits of the larger of the two.
std::string formatMeanStd(const ErrorStatistics& s);

}  // namespace toposlam::evaluation
