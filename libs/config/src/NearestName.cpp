#include <toposlam/config/NearestName.h>

#include <algorithm>
#include <cctype>
#include <numeric>

namespace toposlam::config {

std::size_t editDistance(const std::string& a, const std::string& b) {
    const auto same = [](char x, char y) {
        return std::tolower(static_cast<unsigned char>(x)) ==
               std::tolower(static_cast<unsigned char>(y));
    };
    std::vector<std::size_t> row(b.size() + 1);
    std::iota(row.begin(), row.end(), std::size_t{0});
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min(
                {row[j] + 1, row[j - 1] + 1, diagonal + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

namespace {
/// Edit distance, but a key with its unit suffix left out ("fov" for "fov_deg") or a key of
/// which `name` is the beginning counts as nearly equal.
std::size_t keyDistance(const std::string& name, const std::string& key) {
    std::size_t d = editDistance(name, key);
    const std::string suffix = "_deg";
    if (key.size() > suffix.size() &&
        key.compare(key.size() - suffix.size(), suffix.size(), suffix) == 0)
        d = std::min(d, editDistance(name, key.substr(0, key.size() - suffix.size())) + 1);
    if (name.size() >= 3 && key.size() > name.size() &&
        editDistance(name, key.substr(0, name.size())) == 0)
        d = std::min<std::size_t>(d, 2);
    return d;
}
}  // namespace

std::string nearestName(const std::string& name, const std::vector<std::string>& known) {
    std::string best;
    std::size_t bestDistance = 0;
    for (const std::string& k : known) {
        const std::size_t d = keyDistance(name, k);
        if (best.empty() || d < bestDistance) {
            best = k;
            bestDistance = d;
        }
    }
    return best;
}

std::string unknownNameProblem(const std::string& what, const std::string& name,
                               const std::vector<std::string>& known) {
    const std::string nearest = nearestName(name, known);
    std::string problem = "unknown " + what;
    if (!nearest.empty())
        problem += "; did you mean '" + nearest + "'?";
    return problem;
}

}  // namespace toposlam::config
