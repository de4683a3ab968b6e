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

void simulatedJson(const FeatureBenchmarkReport& report, std::ostringstream& j) {
    const auto& rows = report.simulated;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const SimulatedRow& r = rows[i];
        const auto& s = r.scores;
        j << "    {\"method\": \"" << r.method << "\", \"beams\": " << r.beams << ", \"laser\": \""
          << r.laser << "\", \"sigma\": " << r.sigma << ", \"scans\": " << r.scans
          << ", \"ground_truth_corners\": " << s.groundTruthCorners
          << ", \"detected_corners\": " << s.detectedCorners << ", \"ignored\": " << s.ignored
          << ", \"hits\": " << s.hits << ", \"precision\": " << num(s.precision(), 4)
          << ", \"recall\": " << num(s.recall(), 4)
          << ", \"position_rmse_m\": " << num(s.positionRmse(), 5)
          << ", \"position_rmse_within_8m_m\": " << num(s.positionRmseNear(), 5)
          << ", \"angle_rmse_deg\": " << num(s.angleRmseDeg(), 3)
          << ", \"angle_mean_abs_deg\": " << num(s.angleMeanAbsDeg(), 3)
          << ", \"segment_endpoint_rmse_m\": " << num(s.endpointRmse(), 5)
          << ", \"walls\": " << s.groundTruthRuns << ", \"walls_matched\": " << s.matchedRuns
          << ", \"cpu_us_per_scan\": " << num(r.microseconds, 3)
          << ", \"wall_us_per_scan\": " << num(r.wallMicroseconds, 3) << "}"
          << (i + 1 < rows.size() ? "," : "") << "\n";
    }
}

void realJson(const FeatureBenchmarkReport& report, std::ostringstream& j) {
    const auto& rows = report.real;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const RealLogRow& r = rows[i];
        j << "    {\"method\": \"" << r.method << "\", \"log\": \"" << r.log
          << "\", \"scans\": " << r.scans << ", \"beams\": " << r.beams
          << ", \"segments_per_scan\": " << num(r.segments, 3)
          << ", \"corners_per_scan\": " << num(r.corners, 3)
          << ", \"endpoints_per_scan\": " << num(r.endpoints, 3)
          << ", \"cpu_us_per_scan\": " << num(r.microseconds, 3)
          << ", \"wall_us_per_scan\": " << num(r.wallMicroseconds, 3) << "}"
          << (i + 1 < rows.size() ? "," : "") << "\n";
    }
}

}  // namespace

void printFeatureBenchmark(const FeatureBenchmarkReport& report, std::FILE* out) {
    printSimulated(report, out);
    printReal(report, out);
    printTargets(report, out);
}

std::string featureBenchmarkJson(const FeatureBenchmarkReport& report) {
    std::ostringstream j;
    j << "{\n  \"benchmark\": \"B1\",\n  \"rooms\": " << report.options.rooms
      << ",\n  \"seed\": " << report.options.seed << ",\n  \"simulated\": [\n";
    simulatedJson(report, j);
    j << "  ],\n  \"two_point_vs_least_squares\": [\n";
    const auto& agreements = report.agreements;
    for (std::size_t i = 0; i < agreements.size(); ++i) {
        const auto& a = agreements[i];
        j << "    {\"laser\": \"" << a.laser << "\", \"sigma\": " << a.sigma
          << ", \"pairs\": " << a.agreement.pairs << ", \"mean_m\": " << num(a.agreement.mean, 5)
          << ", \"p95_m\": " << num(a.agreement.p95, 5)
          << ", \"max_m\": " << num(a.agreement.max, 5) << "}"
          << (i + 1 < agreements.size() ? "," : "") << "\n";
    }
    j << "  ],\n  \"real\": [\n";
    realJson(report, j);
    j << "  ]\n}\n";
    return j.str();
}

}  // namespace toposlam::featureeval
