#pragma once
// The values a numeric command-line option accepts, and the one strict parser every app uses for
// numbers: the whole text must be a finite number of the option's type inside the range, so
// "-1" for a count, "nan", "inf", "1e999", "12abc" and "" are all refused (never wrapped,
// clamped or read as 0).
#include <limits>
#include <optional>
#include <string>
#include <type_traits>

namespace toposlam::cli {

namespace detail {
/// Parses all of `text` as a decimal integer / a finite floating-point number; nullopt if it is
/// not one (or does not fit a long long).
std::optional<long long> parseInteger(const std::string& text);
std::optional<double> parseReal(const std::string& text);
/// "[1, 8]", "(0, 3600]": the interval in the usual notation, numbers as short as exact.
std::string formatInterval(double min, double max, bool excludeMin, bool integer);
}  // namespace detail

template <typename T>
struct NumberRange {
    static_assert(std::is_arithmetic_v<T> && !std::is_same_v<T, bool>, "numbers only");

    T min = std::numeric_limits<T>::lowest();
    T max = std::numeric_limits<T>::max();
    bool excludeMin = false;  ///< (min, max] instead of [min, max]

    /// [min, max].
    static NumberRange closed(T min, T max) { return {min, max, false}; }
    /// (0, max]: a positive amount (for integers: 1..max).
    static NumberRange positive(T max) {
        return std::is_integral_v<T> ? NumberRange{T(1), max, false} : NumberRange{T(0), max, true};
    }
    /// [0, max].
    static NumberRange nonNegative(T max) { return {T(0), max, false}; }

    bool contains(T v) const {
        if constexpr (std::is_floating_point_v<T>) {
            if (!(v == v) || v == std::numeric_limits<T>::infinity() ||
                v == -std::numeric_limits<T>::infinity())
                return false;
        }
        return (excludeMin ? v > min : v >= min) && v <= max;
    }

    /// "[1, 8]", "(0, 3600]".
    std::string interval() const {
        return detail::formatInterval(static_cast<double>(min), static_cast<double>(max),
                                      excludeMin, std::is_integral_v<T>);
    }
    /// "an integer in [1, 8]", "a number in (0, 3600]".
    std::string describe() const {
        return std::string(std::is_integral_v<T> ? "an integer" : "a number") + " in " + interval();
    }

    /// The value of `text` when it is a number of type T inside the range; nullopt otherwise.
    std::optional<T> parse(const std::string& text) const {
        if constexpr (std::is_integral_v<T>) {
            const auto v = detail::parseInteger(text);
            // Compared before the cast to T, which could wrap ("-1" for an unsigned count).
            const bool fits =
                v && (*v < 0 ? *v >= static_cast<long long>(min)
                             : max >= T(0) && static_cast<unsigned long long>(*v) <=
                                                  static_cast<unsigned long long>(max));
            if (!fits || !contains(static_cast<T>(*v)))
                return std::nullopt;
            return static_cast<T>(*v);
        } else {
            const auto v = detail::parseReal(text);
            if (!v || !contains(static_cast<T>(*v)))
                return std::nullopt;
            return static_cast<T>(*v);
        }
    }
};

}  // namespace toposlam::cli
