#include <toposlam/featureeval/FeatureBenchmark.h>

#include <algorithm>
#include <sstream>

namespace toposlam::featureeval {

namespace {

std::string num(double v, int precision) {
    if (!std::isfinite(v))
        return "null";
    std::ostringstream s;
    s.precision(precision);
    s << std::fixed << v;
    return s.str();
}

std::string cell(double v, int precision) {
    return std::isfinite(v) ? num(v, precision) : "-";
}

double timeOf(const FeatureBenchmarkReport& report, const std::string& method, std::size_t beams,
              double sigma) {
    for (const SimulatedRow& r : report.simulated) {
        if (r.method == method && r.beams == beams && r.sigma == sigma)
            return r.microseconds;
    }
    return NAN;
}

void printSimulated(const FeatureBenchmarkReport& report, std::FILE* out) {
    const auto& rows = report.simulated;
    std::fprintf(out, "\nB1 simulated: %d rooms, %zu scans per laser and noise level (seed %u)\n\n",
                 report.options.rooms, rows.empty() ? std::size_t{0} : rows.front().scans,
                 report.options.seed);
    std::fprintf(
        out,
        "| method | laser | sigma m | corner P | corner R | pos RMSE m | pos RMSE <= 8 m | angle "
        "err deg RMS / mean | seg endpoint RMSE m | walls matched | CPU us/scan | x split-merge |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const SimulatedRow& r : rows) {
        const bool corners = r.method != "segments";
        const auto& s = r.scores;
        const double ratio = r.microseconds / timeOf(report, "split-merge", r.beams, r.sigma);
        std::fprintf(
            out, "| %s | %s | %.2f | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n",
            r.method.c_str(), r.laser.c_str(), r.sigma,
            corners ? cell(100 * s.precision(), 1).append(" %").c_str() : "-",
            corners ? cell(100 * s.recall(), 1).append(" %").c_str() : "-",
            corners ? cell(s.positionRmse(), 4).c_str() : "-",
            corners ? cell(s.positionRmseNear(), 4).c_str() : "-",
            corners ? (cell(s.angleRmseDeg(), 2) + " / " + cell(s.angleMeanAbsDeg(), 2)).c_str()
                    : "-",
            cell(s.endpointRmse(), 4).c_str(), (cell(100 * s.segmentRecall(), 1) + " %").c_str(),
            cell(r.microseconds, 2).c_str(), cell(ratio, 2).c_str());
    }
    std::fprintf(
        out,
        "\nTwo-point fit vs least squares, same scans: distance between their corners\n\n"
        "| laser | sigma m | pairs | mean m | 95 %% m | max m |\n|---|---|---|---|---|---|\n");
    for (const auto& a : report.agreements) {
        std::fprintf(out, "| %s | %.2f | %zu | %.4f | %.4f | %.4f |\n", a.laser.c_str(), a.sigma,
                     a.agreement.pairs, a.agreement.mean, a.agreement.p95, a.agreement.max);
    }
}

void printReal(const FeatureBenchmarkReport& report, std::FILE* out) {
    if (report.real.empty() && report.messages.empty())
        return;
    std::fprintf(out,
                 "\nB1 real logs: every scan\n\n"
                 "| method | log | scans | beams | segments/scan | corners/scan | "
                 "endpoints/scan | CPU us/scan | x split-merge |\n"
                 "|---|---|---|---|---|---|---|---|---|\n");
    for (const RealLogRow& r : report.real) {
        double sm = NAN;
        for (const RealLogRow& o : report.real) {
            if (o.method == "split-merge" && o.log == r.log)
                sm = o.microseconds;
        }
        std::fprintf(out, "| %s | %s | %zu | %zu | %.1f | %.1f | %.1f | %s | %s |\n",
                     r.method.c_str(), r.log.c_str(), r.scans, r.beams, r.segments, r.corners,
                     r.endpoints, cell(r.microseconds, 2).c_str(),
                     cell(r.microseconds / sm, 2).c_str());
    }
    for (const std::string& m : report.messages)
        std::fprintf(out, "%s\n", m.c_str());
}

/// Targets of the corner extractor (issue 3).
void printTargets(const FeatureBenchmarkReport& report, std::FILE* out) {
    const SimulatedRow* target = nullptr;
    for (const SimulatedRow& r : report.simulated) {
        if (r.method == "corners" && r.beams == 1081 && r.sigma == 0.01)
            target = &r;
    }
    if (!target)
        return;
    const auto& s = target->scores;
    const double t = target->microseconds, sm = timeOf(report, "split-merge", 1081, 0.01);
    double worstAgreement = 0;
    for (const auto& a : report.agreements)
        worstAgreement = std::max(worstAgreement, a.agreement.mean);
    const auto mark = [](bool ok) { return ok ? "met" : "NOT met"; };
    std::fprintf(out,
                 "\nTargets (corners, 1081 beams, sigma 0.01 m):\n"
                 "  CPU time per scan %.2f us <= 20 us: %s; faster than split-merge (%.2f us): %s\n"
                 "  recall %.1f %% >= 95 %%: %s; precision %.1f %% >= 95 %%: %s\n"
                 "  position RMSE within 8 m %.4f m <= 0.02 m: %s; angle error %.2f deg RMS, "
                 "%.2f deg mean <= 1 deg: %s (RMS), %s (mean)\n"
                 "  two-point vs least squares: mean corner distance <= %.4f m <= 0.01 m: %s\n",
                 t, mark(t <= 20), sm, mark(t < sm), 100 * s.recall(), mark(s.recall() >= 0.95),
                 100 * s.precision(), mark(s.precision() >= 0.95), s.positionRmseNear(),
                 mark(s.positionRmseNear() <= 0.02), s.angleRmseDeg(), s.angleMeanAbsDeg(),
                 mark(s.angleRmseDeg() <= 1), mark(s.angleMeanAbsDeg() <= 1), worstAgreement,
                 mark(worstAgreement <= 0.01));
}

double rounded(double v, int decimals) {
    return io::roundDecimals(v, decimals);
}

io::Json simulatedJson(const FeatureBenchmarkReport& report) {
    io::Json simulated = io::Json::array();
    for (const SimulatedRow& r : report.simulated) {
        const auto& s = r.scores;
        simulated.push_back({{"method", r.method},
                             {"beams", r.beams},
                             {"laser", r.laser},
                             {"sigma", r.sigma},
                             {"scans", r.scans},
                             {"ground_truth_corners", s.groundTruthCorners},
                             {"detected_corners", s.detectedCorners},
                             {"ignored", s.ignored},
                             {"hits", s.hits},
                             {"precision", rounded(s.precision(), 4)},
                             {"recall", rounded(s.recall(), 4)},
                             {"position_rmse_m", rounded(s.positionRmse(), 5)},
                             {"position_rmse_within_8m_m", rounded(s.positionRmseNear(), 5)},
                             {"angle_rmse_deg", rounded(s.angleRmseDeg(), 3)},
                             {"angle_mean_abs_deg", rounded(s.angleMeanAbsDeg(), 3)},
                             {"segment_endpoint_rmse_m", rounded(s.endpointRmse(), 5)},
                             {"walls", s.groundTruthRuns},
                             {"walls_matched", s.matchedRuns},
                             {"cpu_us_per_scan", rounded(r.microseconds, 3)},
                             {"wall_us_per_scan", rounded(r.wallMicroseconds, 3)}});
    }
    return simulated;
}

io::Json realJson(const FeatureBenchmarkReport& report) {
    io::Json real = io::Json::array();
    for (const RealLogRow& r : report.real) {
        real.push_back({{"method", r.method},
                        {"log", r.log},
                        {"scans", r.scans},
                        {"beams", r.beams},
                        {"segments_per_scan", rounded(r.segments, 3)},
                        {"corners_per_scan", rounded(r.corners, 3)},
                        {"endpoints_per_scan", rounded(r.endpoints, 3)},
                        {"cpu_us_per_scan", rounded(r.microseconds, 3)},
                        {"wall_us_per_scan", rounded(r.wallMicroseconds, 3)}});
    }
    return real;
}

}  // namespace

void printFeatureBenchmark(const FeatureBenchmarkReport& report, std::FILE* out) {
    printSimulated(report, out);
    printReal(report, out);
    printTargets(report, out);
}

io::Json featureBenchmarkJson(const FeatureBenchmarkReport& report) {
    io::Json agreement = io::Json::array();
    for (const auto& a : report.agreements) {
        agreement.push_back({{"laser", a.laser},
                             {"sigma", a.sigma},
                             {"pairs", a.agreement.pairs},
                             {"mean_m", rounded(a.agreement.mean, 5)},
                             {"p95_m", rounded(a.agreement.p95, 5)},
                             {"max_m", rounded(a.agreement.max, 5)}});
    }
    return {{"benchmark", "B1"},
            {"rooms", report.options.rooms},
            {"seed", report.options.seed},
            {"simulated", simulatedJson(report)},
            {"two_point_vs_least_squares", agreement},
            {"real", realJson(report)}};
}

}  // namespace toposlam::featureeval
