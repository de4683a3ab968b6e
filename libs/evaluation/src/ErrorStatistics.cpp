#include <toposlam/evaluation/ErrorStatistics.h>

#include <algorithm>
#include <cmath>

namespace toposlam::evaluation {

ErrorStatistics summarizeErrors(const std::vector<double>& values) {
    ErrorStatistics s;
    s.count = values.size();
    if (values.empty())
        return s;
    double sum = 0, sumSquares = 0;
    s.max = values.front();
    for (const double v : values) {
        sum += v;
        sumSquares += v * v;
        s.max = std::max(s.max, v);
    }
    const double n = static_cast<double>(values.size());
    s.mean = sum / n;
    s.rms = std::sqrt(sumSquares / n);
    if (values.size() >= 2) {
        double squaredDeviations = 0;
        for (const double v : values)
            squaredDeviations += (v - s.mean) * (v - s.mean);
        s.std = std::sqrt(squaredDeviations / (n - 1));
    }
    return s;
}

}  // namespace toposlam::evaluation
