#include <toposlam/cli/NumberRange.h>

#include <charconv>
#include <cmath>
#include <cstdio>

namespace toposlam::cli::detail {

std::optional<long long> parseInteger(const std::string& text) {
    long long v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (text.empty() || ec != std::errc() || ptr != end)
        return std::nullopt;
    return v;
}

std::optional<double> parseReal(const std::string& text) {
    double v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::string formatInterval(double min, double max, bool excludeMin, bool integer) {
    const auto number = [integer](double v) {
        char buf[32];
        if (integer)
            std::snprintf(buf, sizeof buf, "%.0f", v);
        else
            std::snprintf(buf, sizeof buf, "%g", v);
        return std::string(buf);
    };
    return (excludeMin ? "(" : "[") + number(min) + ", " + number(max) + "]";
}

}  // namespace toposlam::cli::detail
