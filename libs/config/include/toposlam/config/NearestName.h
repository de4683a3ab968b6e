#pragma once
// "Did you mean ...?": the known name closest to a misspelled one, by edit distance.
#include <cstddef>
#include <string>
#include <vector>

namespace toposlam::config {

/// Levenshtein distance (insertions, deletions, substitutions; ASCII case-insensitive, so
/// that "Beams" is 0 from "beams").
std::size_t editDistance(const std::string& a, const std::string& b);

/// The name of `known` nearest to `name` ("" when `known` is empty; the first of equals).
std::string nearestName(const std::string& name, const std::vector<std::string>& known);

/// "unknown key; did you mean 'x'?" for `what` = "key" (or "section", ...).
std::string unknownNameProblem(const std::string& what, const std::string& name,
                               const std::vector<std::string>& known);

}  // namespace toposlam::config
