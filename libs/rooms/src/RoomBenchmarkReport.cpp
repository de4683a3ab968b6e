// RoomBenchmark's reports: the Markdown tables and the JSON file.
#include <toposlam/rooms/RoomBenchmark.h>

#include <toposlam/io/JsonFile.h>

#include <cstdio>
#include <sstream>

namespace toposlam::rooms {

namespace {

std::string pct(double v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%.1f", 100.0 * v);
    return buf;
}

std::string angleText(const std::optional<double>& angle) {
    if (!angle)
        return "all";
    char buf[16];
    std::snprintf(buf, sizeof buf, "%g", *angle);
    return buf;
}

io::Json doorJson(const DoorMatchCounts& d) {
    return {{"virtual_doors", d.virtualDoors}, {"matched_virtual", d.matchedVirtual},
            {"true_doors", d.trueDoors},       {"matched_true", d.matchedTrue},
            {"precision", d.precision()},      {"recall", d.recall()}};
}

io::Json scoreJson(const RoomBenchmarkScore& s) {
    io::Json j = {{"dataset", s.dataset},
                  {"map", s.map},
                  {"furnished", s.furnished},
                  {"rotation_deg", s.rotationDeg},
                  {"method", s.method},
                  {"recall", s.pr.recall},
                  {"precision", s.pr.precision},
                  {"recall_px_weighted", s.pr.recallPixels},
                  {"precision_px_weighted", s.pr.precisionPixels},
                  {"precision_of_rooms", s.pr.precisionOfRooms},
                  {"unassigned_pixels", s.pr.unassignedPixels},
                  {"segments", s.segments},
                  {"ground_truth_rooms", s.groundTruthRooms},
                  {"room_recall", s.pr.roomRecall},
                  {"room_pixels", s.pr.roomPixels},
                  {"doors_0.5m", doorJson(s.doors)},
                  {"doors_1.0m", doorJson(s.doors1m)},
                  {"seconds_median", s.seconds},
                  {"seconds_min", s.minSeconds},
                  {"cpu_seconds_median", s.cpuSeconds}};
    if (s.openFloor) {
        j["open_floor"] = {{"recall", s.openFloor->recall},
                           {"precision", s.openFloor->precision},
                           {"room_recall", s.openFloor->roomRecall},
                           {"room_pixels", s.openFloor->roomPixels}};
    }
    return j;
}

io::Json summaryJson(const RoomBenchmarkSummary& m) {
    return {{"dataset", m.dataset},
            {"method", m.method},
            {"group", m.group},
            {"rotation_deg", m.rotationDeg ? io::Json(*m.rotationDeg) : io::Json()},
            {"maps", m.maps},
            {"recall_mean", m.recallMean},
            {"recall_sd", m.recallSd},
            {"precision_mean", m.precisionMean},
            {"precision_sd", m.precisionSd},
            {"recall_px_weighted", m.recallPixels},
            {"precision_px_weighted", m.precisionPixels},
            {"seconds_mean", m.secondsMean},
            {"seconds_max", m.secondsMax},
            {"min_seconds_mean", m.minSecondsMean},
            {"cpu_seconds_mean", m.cpuSecondsMean},
            {"segments", m.segments},
            {"ground_truth_rooms", m.groundTruthRooms},
            {"doors_0.5m_pooled", doorJson(m.doors)},
            {"doors_1.0m_pooled", doorJson(m.doors1m)},
            {"door_precision_mean_of_maps", m.doorPrecisionMeanOfMaps},
            {"door_recall_mean_of_maps", m.doorRecallMeanOfMaps}};
}

}  // namespace

std::string RoomBenchmark::summaryTable(const std::vector<RoomBenchmarkSummary>& summary) {
    std::ostringstream o;
    char buf[640];
    o << "| set | method | maps | angle ° | recall (mean ± sd) | precision (mean ± sd) | recall "
         "px-weighted | precision px-weighted | runtime s: median-of-repeats, mean / max (mean "
         "of min; CPU) | segments / GT rooms (sum) | door P (pooled) | door R (pooled) | door P "
         "/ R (mean of maps) | door P / R at 1.0 m (pooled) |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& m : summary) {
        std::snprintf(
            buf, sizeof buf,
            "| %s | %s | %s | %s | %s ± %s %% | %s ± %s %% | %s %% | %s %% | %.3f / %.3f "
            "(%.3f; %.3f) | %d / %d | %s %% (%zu/%zu) | %s %% (%zu/%zu) | %s / %s %% | %s / %s "
            "%% |\n",
            m.dataset.c_str(), m.method.c_str(), m.group.c_str(), angleText(m.rotationDeg).c_str(),
            pct(m.recallMean).c_str(), pct(m.recallSd).c_str(), pct(m.precisionMean).c_str(),
            pct(m.precisionSd).c_str(), pct(m.recallPixels).c_str(), pct(m.precisionPixels).c_str(),
            m.secondsMean, m.secondsMax, m.minSecondsMean, m.cpuSecondsMean, m.segments,
            m.groundTruthRooms, pct(m.doors.precision()).c_str(), m.doors.matchedVirtual,
            m.doors.virtualDoors, pct(m.doors.recall()).c_str(), m.doors.matchedTrue,
            m.doors.trueDoors, pct(m.doorPrecisionMeanOfMaps).c_str(),
            pct(m.doorRecallMeanOfMaps).c_str(), pct(m.doors1m.precision()).c_str(),
            pct(m.doors1m.recall()).c_str());
        o << buf;
    }
    return o.str();
}

std::string RoomBenchmark::table(const std::vector<RoomBenchmarkScore>& scores,
                                 const std::vector<RoomBenchmarkSummary>& summary) {
    std::ostringstream o;
    char buf[512];
    o << "| set | map | angle ° | method | recall % | precision % | segments / GT | door P % | "
         "door R % | time s | CPU s |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& s : scores) {
        std::snprintf(buf, sizeof buf,
                      "| %s | %s | %g | %s | %s | %s | %d / %d | %s (%zu/%zu) | %s (%zu/%zu) | "
                      "%.3f | %.3f |\n",
                      s.dataset.c_str(), s.map.c_str(), s.rotationDeg, s.method.c_str(),
                      pct(s.pr.recall).c_str(), pct(s.pr.precision).c_str(), s.segments,
                      s.groundTruthRooms, pct(s.doors.precision()).c_str(), s.doors.matchedVirtual,
                      s.doors.virtualDoors, pct(s.doors.recall()).c_str(), s.doors.matchedTrue,
                      s.doors.trueDoors, s.seconds, s.cpuSeconds);
        o << buf;
    }
    o << "\n" << summaryTable(summary);
    return o.str();
}

std::string RoomBenchmark::json(const std::vector<RoomBenchmarkScore>& scores,
                                const std::vector<RoomBenchmarkSummary>& summary,
                                const RoomBenchmarkOptions& options) {
    io::Json j;
    j["benchmark"] = "B4 room segmentation";
    j["data_dir"] = options.dataDir;
    j["repeats"] = options.repeats;
    j["rotations_deg"] = options.rotationsDeg;
    j["cell_size_m"] = options.cellSize > 0 ? io::Json(options.cellSize) : io::Json();
    j["maps"] = io::Json::array();
    for (const auto& s : scores)
        j["maps"].push_back(scoreJson(s));
    j["summary"] = io::Json::array();
    for (const auto& m : summary)
        j["summary"].push_back(summaryJson(m));
    return io::formatJson(j);
}

}  // namespace toposlam::rooms
