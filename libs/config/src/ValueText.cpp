#include "ValueText.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace toposlam::config::detail {

std::string trim(const std::string& text) {
    const auto blank = [](unsigned char c) { return std::isspace(c) != 0; };
    auto begin = std::find_if_not(text.begin(), text.end(), blank);
    auto end = std::find_if_not(text.rbegin(), text.rend(), blank).base();
    return begin < end ? std::string(begin, end) : std::string();
}

std::optional<double> parseReal(const std::string& text) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text.front())))
        return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || !std::isfinite(v) || errno == ERANGE)
        return std::nullopt;
    return v;
}

std::string notANumberProblem(const std::string& text) {
    if (text.find('#') != std::string::npos || text.find(';') != std::string::npos)
        return "not a number (comments go on a line of their own)";
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (!text.empty() && end == text.c_str() + text.size() && !std::isfinite(v))
        return "must be a finite number";
    return "not a number";
}

std::optional<long long> parseInteger(const std::string& text) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text.front())))
        return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(text.c_str(), &end, 10);
    if (end != text.c_str() + text.size() || errno == ERANGE)
        return std::nullopt;
    return v;
}

std::optional<bool> parseFlag(const std::string& text) {
    std::string t = text;
    std::transform(t.begin(), t.end(), t.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (t == "true" || t == "1" || t == "yes" || t == "on")
        return true;
    if (t == "false" || t == "0" || t == "no" || t == "off")
        return false;
    return std::nullopt;
}

namespace {
/// `digits` significant digits of v, without an exponent for everyday magnitudes.
std::string significant(double v, int digits) {
    char buffer[64];
    const double magnitude = std::abs(v);
    if (magnitude >= 1e-4 && magnitude < 1e15) {
        const int exponent = static_cast<int>(std::floor(std::log10(magnitude)));
        std::snprintf(buffer, sizeof buffer, "%.*f", std::max(0, digits - 1 - exponent), v);
    } else {
        std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
    }
    return buffer;
}
}  // namespace

std::string formatReal(double codeValue, const std::function<double(double)>& toFile,
                       const std::function<double(double)>& fromFile) {
    double value = codeValue;
    for (int attempt = 0; attempt < 4; ++attempt) {
        const double fileValue = toFile(value);
        for (int digits = 1; digits <= 17; ++digits) {
            const std::string text = significant(fileValue, digits);
            if (fromFile(std::strtod(text.c_str(), nullptr)) == value)
                return text;
        }
        // No decimal reads back as `value` (degrees -> radians cannot reach every double):
        // go on with the value the nearest decimal reads as (1 ulp away). Its text reads back
        // as itself, so saving what was loaded writes the same file again.
        value = fromFile(std::strtod(significant(fileValue, 17).c_str(), nullptr));
    }
    return significant(toFile(value), 17);
}

}  // namespace toposlam::config::detail
