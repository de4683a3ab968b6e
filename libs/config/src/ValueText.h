#pragma once
// Values as text in an options file: strict parsing (the whole text, finite numbers, exact
// integers) and writing numbers so that they read back as the same value.
#include <functional>
#include <optional>
#include <string>

namespace toposlam::config::detail {

/// `text` without leading and trailing blanks.
std::string trim(const std::string& text);

/// Why `text` is no finite number: NaN / inf, a trailing comment, or anything else.
std::string notANumberProblem(const std::string& text);

/// The finite number `text` spells, or nullopt (empty, trailing characters, NaN, inf, overflow).
std::optional<double> parseReal(const std::string& text);
/// The integer `text` spells in decimal, or nullopt (also when beyond long long).
std::optional<long long> parseInteger(const std::string& text);
/// true / false / 1 / 0 / yes / no / on / off (case-insensitive), or nullopt.
std::optional<bool> parseFlag(const std::string& text);

/// The shortest decimal text t of toFile(codeValue) such that fromFile(t) == codeValue exactly
/// (so a saved file reads back bit for bit). When no text does (degrees of some radian values),
/// that of the nearest value that has one (1 ulp away), which then saves as itself.
std::string formatReal(double codeValue, const std::function<double(double)>& toFile,
                       const std::function<double(double)>& fromFile);

}  // namespace toposlam::config::detail
