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

/// The shortest decimal text t of fileValue such that fromFile(t) == codeValue exactly (so a
/// saved file reads back bit for bit); 17 significant digits when no text does.
std::string formatReal(double fileValue, double codeValue,
                       const std::function<double(double)>& fromFile);

}  // namespace toposlam::config::detail
