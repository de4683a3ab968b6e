#include <mrpt/math/wrap2pi.h>
#include <toposlam/io/JsonFile.h>
#include <toposlam/matchingbench/MatchingBenchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>

namespace toposlam::matchingbench {

namespace {
constexpr double kMaxTranslationError = 0.1;  // m, per axis (Li et al. 2016)
constexpr double kMaxRotationError = 0.03;    // rad

double quantile(std::vector<double> v, double q) {
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t k = std::min(v.size() - 1, std::size_t(q * double(v.size())));
    return v[k];
}
}  // namespace

bool isSuccess(const mrpt::poses::CPose2D& estimate, const mrpt::poses::CPose2D& truth) {
    return std::abs(estimate.x() - truth.x()) < kMaxTranslationError &&
           std::abs(estimate.y() - truth.y()) < kMaxTranslationError &&
           std::abs(mrpt::math::wrapToPi(estimate.phi() - truth.phi())) < kMaxRotationError;
}

void runBenchmark(const ScanPairs& pairs, const std::vector<PairMatcher*>& methods,
                  bool useOdometryGuess, BenchmarkReport& report,
                  const std::function<void(std::size_t, std::size_t)>& progress) {
    std::vector<std::string> sets;
    for (const ScanPair& p : pairs)
        if (std::find(sets.begin(), sets.end(), p.set) == sets.end())
            sets.push_back(p.set);
    struct Accumulated {
        MethodResult result;
        std::vector<double> translation, rotation, seconds, matchSeconds;
    };
    std::map<std::pair<std::size_t, std::size_t>, Accumulated> acc;  // (set, method)

    std::size_t done = 0;
    for (const ScanPair& pair : pairs) {
        const std::size_t s =
            std::size_t(std::find(sets.begin(), sets.end(), pair.set) - sets.begin());
        const std::optional<mrpt::poses::CPose2D> guess =
            useOdometryGuess ? std::optional<mrpt::poses::CPose2D>(pair.odometry) : std::nullopt;
        for (std::size_t m = 0; m < methods.size(); ++m) {
            const PairOutcome o = methods[m]->match(pair, guess);
            Accumulated& a = acc[{s, m}];
            MethodResult& r = a.result;
            ++r.pairs;
            const bool ok = o.answered && isSuccess(o.pose, pair.truth);
            r.successes += ok ? 1 : 0;
            r.answered += o.answered ? 1 : 0;
            r.wrong += o.answered && !ok ? 1 : 0;
            a.translation.push_back(
                std::hypot(o.pose.x() - pair.truth.x(), o.pose.y() - pair.truth.y()));
            a.rotation.push_back(std::abs(mrpt::math::wrapToPi(o.pose.phi() - pair.truth.phi())));
            a.seconds.push_back(o.seconds);
            a.matchSeconds.push_back(o.matchSeconds);
        }
        if (progress)
            progress(++done, pairs.size());
    }
    for (std::size_t s = 0; s < sets.size(); ++s) {
        for (std::size_t m = 0; m < methods.size(); ++m) {
            Accumulated& a = acc[{s, m}];
            MethodResult r = a.result;
            r.method = methods[m]->name();
            r.set = sets[s];
            r.mode = useOdometryGuess ? "odometry-guess" : "zero-guess";
            r.medianTranslationError = quantile(a.translation, 0.5);
            r.medianRotationError = quantile(a.rotation, 0.5);
            r.medianSeconds = quantile(a.seconds, 0.5);
            r.p95Seconds = quantile(a.seconds, 0.95);
            r.medianMatchSeconds = quantile(a.matchSeconds, 0.5);
            report.results.push_back(r);
        }
    }
}

void BenchmarkReport::printTable(std::ostream& out) const {
    char line[512];
    std::snprintf(line, sizeof line, "%-15s %-14s %-26s %6s %8s %7s %9s %9s %9s %9s %9s\n", "mode",
                  "set", "method", "pairs", "success", "wrong", "med e_t", "med e_r", "med ms",
                  "p95 ms", "match ms");
    out << line;
    out << std::string(std::char_traits<char>::length(line) - 1, '-') << "\n";
    std::string lastMode;
    for (const MethodResult& r : results) {
        std::snprintf(
            line, sizeof line,
            "%-15s %-14s %-26s %6zu %7.1f%% %6.1f%% %7.3f m %6.2f deg %9.3f %9.3f %9.3f\n",
            r.mode.c_str(), r.set.c_str(), r.method.c_str(), r.pairs, 100.0 * r.successRate(),
            100.0 * r.wrongRate(), r.medianTranslationError, r.medianRotationError * 180.0 / M_PI,
            1e3 * r.medianSeconds, 1e3 * r.p95Seconds, 1e3 * r.medianMatchSeconds);
        out << line;
    }
}

void BenchmarkReport::writeJson(const std::string& path) const {
    io::Json rows = io::Json::array();
    for (const MethodResult& r : results) {
        rows.push_back({{"mode", r.mode},
                        {"set", r.set},
                        {"method", r.method},
                        {"pairs", r.pairs},
                        {"successes", r.successes},
                        {"answered", r.answered},
                        {"wrong", r.wrong},
                        {"success_rate", r.successRate()},
                        {"median_translation_error_m", r.medianTranslationError},
                        {"median_rotation_error_rad", r.medianRotationError},
                        {"median_seconds", r.medianSeconds},
                        {"p95_seconds", r.p95Seconds},
                        {"median_match_seconds", r.medianMatchSeconds}});
    }
    io::saveJsonFile(
        {{"benchmark", "B2 scan matching"},
         {"success", "|ex|, |ey| < 0.1 m and |etheta| < 0.03 rad, answered"},
         {"time", "CPU seconds of the matching thread per pair, from the two raw scans"},
         {"results", rows}},
        path);
}

}  // namespace toposlam::matchingbench
