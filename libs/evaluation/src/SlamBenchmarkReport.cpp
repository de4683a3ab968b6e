#include <toposlam/evaluation/SlamBenchmarkReport.h>
#include <toposlam/evaluation/SlamEvaluation.h>
#include <toposlam/io/AtomicFile.h>
#include <toposlam/io/LaserPosition.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace toposlam::evaluation {

namespace {

constexpr double kMiB = 1024.0 * 1024.0;
const char* const kNone = "–";

// 1234× / 56.7×: real-time factors, whole numbers from 10 up.
std::string factor(double duration, double seconds) {
    if (!(seconds > 0))
        return kNone;
    const double f = duration / seconds;
    return formatFixed(f, f >= 10 ? 0 : 1) + "×";
}

// ", 4 repeating an earlier line" when the relation file has repeats (scored as published).
std::string repeatedNote(const SlamBenchmarkLogResult& log) {
    if (log.repeatedRelations == 0)
        return "";
    return ", " + std::to_string(log.repeatedRelations) + " repeating an earlier line";
}

// ", scored at the laser, 0.220 m ahead and 0.000 m left of the robot's centre" when the log's
// laser is off centre (relation files are made in the laser's frame: LaserFrame.h).
std::string laserNote(const SlamBenchmarkLogResult& log) {
    if (!log.laserPosition)
        return "";
    return ", scored at the laser, " + io::describeLaserPosition(*log.laserPosition);
}

std::string logLine(const SlamBenchmarkLogResult& log) {
    std::string line = log.log.name + " (" + log.log.logFile + ": ";
    if (!log.error.empty() && log.scans == 0)
        return line + "not read)";
    line += std::to_string(log.scans) + " scans, " + formatFixed(log.durationSeconds, 0) + " s; ";
    if (log.log.groundTruthFile.empty())
        return line + std::to_string(log.relations) + " relations" + repeatedNote(log) +
               laserNote(log) + ")";
    return line + "ground truth " + log.log.groundTruthFile + ": " + std::to_string(log.relations) +
           " derived relations + ATE)";
}

std::string header(const SlamBenchmarkResult& result) {
    std::ostringstream out;
    out << "B3: every SLAM engine on every log, one run after the other, each as a child process "
           "(wall time, CPU time = user + system, peak RSS of that process alone).\n"
        << "Metric: Kümmerle et al. 2009, e = δ_gt⁻¹ ⊕ δ_est, δ_est = x_t1⁻¹ ⊕ x_t2; mean ± "
           "sample std; ATE RMSE / max after the best rigid alignment (ground-truth logs). "
           "Real-time factor = log duration / wall time and / CPU time.\n"
        << "Machine: " << result.cores << " hardware threads, 1-minute load average "
        << (result.loadAverageBefore >= 0 ? formatFixed(result.loadAverageBefore, 1) : "?")
        << " before and "
        << (result.loadAverageAfter >= 0 ? formatFixed(result.loadAverageAfter, 1) : "?")
        << " after the runs (other load inflates wall time, not CPU time).\n"
        << "Logs:\n";
    for (const SlamBenchmarkLogResult& log : result.logs)
        out << "- " << logLine(log) << "\n";
    return out.str();
}

// `count` empty cells.
std::string dashes(int count) {
    std::string cells;
    for (int i = 0; i < count; ++i)
        cells += std::string(" ") + kNone + " |";
    return cells;
}

// The accuracy columns after "relations matched" (6, or 7 with the ATE).
int accuracyColumns(bool withAte) {
    return withAte ? 6 : 5;
}

std::string accuracyCells(const SlamBenchmarkRow& row, bool withAte) {
    if (!row.evaluation)
        return dashes(1 + accuracyColumns(withAte));
    if (row.evaluation->relative.matchedRelations == 0) {
        return " 0 / " + std::to_string(row.evaluation->relative.totalRelations) + " |" +
               dashes(accuracyColumns(withAte));
    }
    std::string cells;
    const RelativePoseErrorResult& r = row.evaluation->relative;
    cells = " " + std::to_string(r.matchedRelations) + " / " + std::to_string(r.totalRelations) +
            " | " + formatMeanStd(r.translation, 4) + " | " + formatMeanStd(r.rotation, 3) + " | " +
            formatMeanStd(r.translationSquared) + " | " + formatMeanStd(r.rotationSquared) + " | " +
            formatFixed(r.translation.max, 4) + " / " + formatFixed(r.rotation.max, 3) + " |";
    if (withAte) {
        const auto& a = row.evaluation->absolute;
        cells += a && a->matchedPoses > 0 ? " " + formatFixed(a->position.rms, 4) + " / " +
                                                formatFixed(a->position.max, 4) + " |"
                                          : dashes(1);
    }
    return cells;
}

std::string costCells(const SlamBenchmarkRow& row, double duration) {
    const SlamEngineRun& run = row.run;
    const bool ran = run.status != SlamEngineRun::Status::Skipped && run.process.wallSeconds > 0;
    if (!ran)
        return dashes(4);
    const ChildProcessResult& p = run.process;
    return " " + formatFixed(p.wallSeconds, 1) + " | " + formatFixed(p.cpuSeconds(), 1) + " | " +
           factor(duration, p.wallSeconds) + " / " + factor(duration, p.cpuSeconds()) + " | " +
           formatFixed(double(p.peakRssBytes) / kMiB, 0) + " |";
}

std::string loopCells(const SlamBenchmarkRow& row) {
    const nlohmann::json& summary = row.run.summary;
    if (!summary.is_object() || !summary.contains("loops"))
        return dashes(1);
    const nlohmann::json& loops = summary["loops"];
    return " " + std::to_string(loops.value("accepted", 0)) + " / " +
           std::to_string(loops.value("rejected", 0)) + " / " +
           std::to_string(loops.value("withdrawn", 0)) + " |";
}

// "failed [2]", "graph [1]": the row's label, with its note numbered in `notes`.
std::string labelled(const std::string& label, const std::string& note,
                     std::vector<std::string>& notes) {
    if (note.empty())
        return label;
    notes.push_back(note);
    return label + " [" + std::to_string(notes.size()) + "]";
}

std::string rowLine(const SlamBenchmarkLogResult& log, const SlamBenchmarkRow& row, bool withAte,
                    std::vector<std::string>& notes) {
    const SlamEngineRun& run = row.run;
    const std::string engine = engineName(run.engine);
    std::string line = "| " + log.log.name + " | ";
    if (run.status == SlamEngineRun::Status::Ok) {
        line +=
            labelled(engine, run.note.empty() ? "" : log.log.name + " " + engine + ": " + run.note,
                     notes) +
            " |" + accuracyCells(row, withAte);
    } else {
        const char* status = run.status == SlamEngineRun::Status::Skipped ? "not run" : "FAILED";
        line += engine + " | " +
                labelled(status, log.log.name + " " + engine + ": " + run.note, notes) + " |" +
                dashes(accuracyColumns(withAte));
    }
    return line + costCells(row, log.durationSeconds) + loopCells(row) + "\n";
}

// The summariseByGroup() table, "" when there is none.
std::string groupTable(const SlamBenchmarkResult& result) {
    const std::vector<SlamGroupSummary> groups = summariseByGroup(result);
    if (groups.empty())
        return "";
    std::ostringstream out;
    out << "\nSimulated logs by robot, over every plan and seed (one tour's outcome is partly "
           "chance: the spread and the worst log say as much as the mean):\n\n"
        << "| robot | engine | logs scored | ATE RMSE mean ± std (m) | median (m) | worst (m): "
           "log | translational error, mean of logs (m) |\n|---|---|---|---|---|---|---|\n";
    for (const SlamGroupSummary& g : groups) {
        out << "| " << g.group << " | " << engineName(g.engine) << " | " << g.ate.count << " / "
            << g.logs << " |";
        if (g.ate.count == 0) {
            out << dashes(4) << "\n";
            continue;
        }
        out << " " << formatMeanStd(g.ate, 4) << " | " << formatFixed(g.ateMedian, 4) << " | "
            << formatFixed(g.ate.max, 4) << ": " << g.worstLog << " | "
            << formatFixed(g.translationMean, 4) << " |\n";
    }
    return out.str();
}

}  // namespace

std::vector<SlamGroupSummary> summariseByGroup(const SlamBenchmarkResult& result) {
    std::vector<SlamGroupSummary> out;
    // Per summary, its scored logs: (ATE RMSE, mean translational error, log name).
    struct Scored {
        double ate, translation;
        std::string log;
    };
    std::vector<std::vector<Scored>> scored;
    for (const SlamBenchmarkLogResult& log : result.logs) {
        if (log.log.group.empty())
            continue;
        for (const SlamBenchmarkRow& row : log.rows) {
            const auto it = std::find_if(out.begin(), out.end(), [&](const SlamGroupSummary& g) {
                return g.group == log.log.group && g.engine == row.run.engine;
            });
            const std::size_t k = std::size_t(it - out.begin());
            if (it == out.end()) {
                SlamGroupSummary g;
                g.group = log.log.group;
                g.engine = row.run.engine;
                out.push_back(g);
                scored.emplace_back();
            }
            ++out[k].logs;
            if (row.run.status == SlamEngineRun::Status::Failed) {
                ++out[k].failed;
                continue;
            }
            if (!row.evaluation || !row.evaluation->absolute ||
                row.evaluation->absolute->matchedPoses == 0)
                continue;  // skipped, or nothing to score
            scored[k].push_back({row.evaluation->absolute->position.rms,
                                 row.evaluation->relative.translation.mean, log.log.name});
        }
    }
    for (std::size_t k = 0; k < out.size(); ++k) {
        std::vector<double> ates, translations;
        for (const Scored& s : scored[k])
            ates.push_back(s.ate), translations.push_back(s.translation);
        out[k].ate = summarizeErrors(ates);
        if (ates.empty())
            continue;
        out[k].translationMean = summarizeErrors(translations).mean;
        out[k].worstLog =
            std::max_element(scored[k].begin(), scored[k].end(),
                             [](const Scored& a, const Scored& b) { return a.ate < b.ate; })
                ->log;
        std::sort(ates.begin(), ates.end());
        const std::size_t n = ates.size();
        out[k].ateMedian = n % 2 ? ates[n / 2] : 0.5 * (ates[n / 2 - 1] + ates[n / 2]);
    }
    return out;
}

std::string formatSlamBenchmarkTable(const SlamBenchmarkResult& result) {
    const bool withAte =
        std::any_of(result.logs.begin(), result.logs.end(),
                    [](const SlamBenchmarkLogResult& l) { return !l.log.groundTruthFile.empty(); });
    std::ostringstream out;
    out << header(result) << "\n";
    out << "| log | engine | relations matched | translational error (m) | rotational error "
           "(deg) | squared transl. (m²) | squared rot. (deg²) | max transl. (m) / rot. (deg) |"
        << (withAte ? " ATE RMSE / max (m) |" : "")
        << " wall (s) | CPU (s) | real time × (wall / CPU) | peak RSS (MiB) | loops accepted / "
           "rejected / withdrawn |\n|---|---|---|---|---|---|---|---|"
        << (withAte ? "---|" : "") << "---|---|---|---|---|\n";
    std::vector<std::string> notes;
    for (const SlamBenchmarkLogResult& log : result.logs) {
        if (log.rows.empty()) {
            out << "| " << log.log.name << " | " << kNone << " | "
                << labelled("FAILED", log.log.name + ": " + log.error, notes) << " |"
                << dashes(accuracyColumns(withAte) + 5) << "\n";
            continue;
        }
        for (const SlamBenchmarkRow& row : log.rows)
            out << rowLine(log, row, withAte, notes);
        if (!log.error.empty())
            notes.push_back(log.log.name + ": " + log.error);
    }
    if (!notes.empty()) {
        out << "\n";
        for (std::size_t i = 0; i < notes.size(); ++i)
            out << "[" << i + 1 << "] " << notes[i] << "\n";
    }
    out << groupTable(result);
    return out.str();
}

namespace {

nlohmann::json processJson(const ChildProcessResult& p, double duration) {
    return {{"exit_code", p.exitCode},
            {"signal", p.signal},
            {"timed_out", p.timedOut},
            {"wall_s", p.wallSeconds},
            {"cpu_s", p.cpuSeconds()},
            {"user_cpu_s", p.userCpuSeconds},
            {"system_cpu_s", p.systemCpuSeconds},
            {"real_time_factor", p.wallSeconds > 0 ? duration / p.wallSeconds : 0.0},
            {"real_time_factor_cpu", p.cpuSeconds() > 0 ? duration / p.cpuSeconds() : 0.0},
            {"peak_rss_mib", double(p.peakRssBytes) / kMiB}};
}

nlohmann::json rowJson(const SlamBenchmarkRow& row, double duration) {
    const SlamEngineRun& run = row.run;
    const char* status = run.status == SlamEngineRun::Status::Ok       ? "ok"
                         : run.status == SlamEngineRun::Status::Failed ? "failed"
                                                                       : "skipped";
    nlohmann::json j = {{"engine", engineName(run.engine)}, {"status", status}, {"note", run.note}};
    if (run.status != SlamEngineRun::Status::Skipped)
        j["process"] = processJson(run.process, duration);
    if (run.conversion)
        j["conversion"] = processJson(*run.conversion, duration);
    if (row.evaluation)
        j["accuracy"] = evaluationJson(*row.evaluation);
    if (!run.summary.is_null())
        j["summary"] = run.summary;
    return j;
}

}  // namespace

nlohmann::json slamBenchmarkJson(const SlamBenchmarkResult& result) {
    nlohmann::json groups = nlohmann::json::array();
    for (const SlamGroupSummary& g : summariseByGroup(result))
        groups.push_back({{"robot", g.group},
                          {"engine", engineName(g.engine)},
                          {"logs", g.logs},
                          {"failed", g.failed},
                          {"scored", g.ate.count},
                          {"ate_rms_mean_m", g.ate.mean},
                          {"ate_rms_std_m", g.ate.std},
                          {"ate_rms_median_m", g.ateMedian},
                          {"ate_rms_max_m", g.ate.max},
                          {"worst_log", g.worstLog},
                          {"translation_error_mean_m", g.translationMean}});
    nlohmann::json logs = nlohmann::json::array();
    for (const SlamBenchmarkLogResult& log : result.logs) {
        nlohmann::json runs = nlohmann::json::array();
        for (const SlamBenchmarkRow& row : log.rows)
            runs.push_back(rowJson(row, log.durationSeconds));
        const bool truth = !log.log.groundTruthFile.empty();
        logs.push_back({{"name", log.log.name},
                        {"log", log.log.logFile},
                        {"reference",
                         {{"kind", truth ? "ground_truth" : "relations"},
                          {"file", truth ? log.log.groundTruthFile : log.log.relationsFile},
                          {"relations", log.relations},
                          {"repeated_relations", log.repeatedRelations},
                          {"laser_position_m",
                           log.laserPosition
                               ? nlohmann::json::array({log.laserPosition->x, log.laserPosition->y})
                               : nlohmann::json()}}},
                        {"scans", log.scans},
                        {"duration_s", log.durationSeconds},
                        {"error", log.error},
                        {"images", log.images},
                        {"runs", runs}});
    }
    return {{"tool", "toposlam-bench-slam"},
            {"benchmark", "B3"},
            {"metric",
             "Kuemmerle et al. 2009 relation error e = inv(delta_gt) (+) delta_est, delta_est = "
             "inv(x_t1) (+) x_t2; std is the sample std (n-1); ATE after the best rigid 2D "
             "alignment"},
            {"machine",
             {{"hardware_threads", result.cores},
              {"load_average_before", result.loadAverageBefore},
              {"load_average_after", result.loadAverageAfter}}},
            {"work_directory", result.workDirectory},
            {"logs", logs},
            {"by_robot", groups}};
}

void saveSlamBenchmarkJson(const SlamBenchmarkResult& result, const std::string& path) {
    const std::string text = slamBenchmarkJson(result).dump(2) + "\n";
    io::writeFileAtomically(path, [&](const std::string& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        out.close();
        if (!out)
            throw std::runtime_error(path + ": cannot write the JSON file");
    });
}

}  // namespace toposlam::evaluation
