#include <toposlam/evaluation/ErrorStatistics.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

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

std::string formatFixed(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

int significantDecimals(double reference) {
    if (!(std::abs(reference) > 0))
        return 4;
    const int magnitude = static_cast<int>(std::floor(std::log10(std::abs(reference))));
    return std::clamp(3 - magnitude, 0, 8);
}

std::string formatMeanStd(const ErrorStatistics& s, int decimals) {
    return formatFixed(s.mean, decimals) + " ± " + formatFixed(s.std, decimals);
}

std::string formatMeanStd(const ErrorStatistics& s) {
    return formatMeanStd(s, significantDecimals(std::max(s.mean, s.std)));
}

}  // namespace toposlam::evaluation
