#include <toposlam/io/InputError.h>
#include <toposlam/io/JsonFile.h>
#include <toposlam/rooms/DistanceSegmentation.h>
#include <toposlam/rooms/MorphologicalSegmentation.h>
#include <toposlam/rooms/RoomBenchmark.h>
#include <toposlam/rooms/TopologicalMapRendering.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

namespace toposlam::rooms {

namespace {

constexpr double kResolution = 0.05;  // m/pixel of every benchmark map (SOURCES.md)

cv::Mat readGrey(const std::string& path) {
    cv::Mat img = cv::imread(path, cv::IMREAD_GRAYSCALE);
    if (img.empty())
        throw io::InputError(path, "missing or not a readable image");
    return img;
}

// The package's client: grey >= 250 is free (255), the rest not (0).
cv::Mat freeOf(const cv::Mat& grey) {
    cv::Mat out;
    cv::threshold(grey, out, 249, 255, cv::THRESH_BINARY);
    return out;
}

// The grid a SLAM run would hand over: free cells p(free) = 1, the rest 0; origin (0, 0).
mrpt::maps::COccupancyGridMap2D gridOf(const cv::Mat& free) {
    mrpt::maps::COccupancyGridMap2D grid;
    grid.setSize(0, static_cast<float>(free.cols * kResolution), 0,
                 static_cast<float>(free.rows * kResolution), static_cast<float>(kResolution),
                 0.0f);
    for (int r = 0; r < free.rows; ++r) {
        for (int c = 0; c < free.cols; ++c) {
            if (free.at<std::uint8_t>(r, c) != 0)
                grid.setCell(c, free.rows - 1 - r, 1.0f);
        }
    }
    return grid;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v[v.size() / 2];
}

double ratio(std::size_t a, std::size_t b) {
    return b == 0 ? 0.0 : static_cast<double>(a) / b;
}

std::string pct(double v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%.1f", 100.0 * v);
    return buf;
}

}  // namespace

const std::vector<std::string>& RoomBenchmark::benchmarkMaps() {
    static const std::vector<std::string> maps = {
        "lab_ipa",   "lab_c_scan",       "Freiburg52_scan", "Freiburg79_scan", "lab_b_scan",
        "lab_intel", "Freiburg101_scan", "lab_d_scan",      "lab_f_scan",      "lab_a_scan",
        "NLB",       "office_a",         "office_b",        "office_c",        "office_d",
        "office_e",  "office_f",         "office_g",        "office_h",        "office_i"};
    return maps;
}

const std::vector<std::string>& RoomBenchmark::methodNames() {
    static const std::vector<std::string> names = {"vdoor", "vdoor-paper", "morph", "dist"};
    return names;
}

RoomBenchmark::RoomBenchmark(RoomBenchmarkOptions options) : options_(std::move(options)) {
    if (options_.methods.empty())
        options_.methods = methodNames();
    if (options_.maps.empty())
        options_.maps = benchmarkMaps();
    for (const std::string& m : options_.methods) {
        if (std::find(methodNames().begin(), methodNames().end(), m) == methodNames().end()) {
            throw std::invalid_argument("unknown method '" + m +
                                        "' (vdoor, vdoor-paper, morph, dist)");
        }
    }
    options_.repeats = std::max(1, options_.repeats);
}

cv::Mat RoomBenchmark::scoredLabels(const TopologicalMap& map, const cv::Mat& freeImage) {
    cv::Mat labels = map.labels.clone();
    labels.setTo(kUnassignedLabel, (labels == 0) & (freeImage != 0));
    return labels;
}

std::vector<RoomBenchmarkScore> RoomBenchmark::run(
    const std::function<void(std::size_t, std::size_t, const std::string&)>& progress) const {
    namespace fs = std::filesystem;
    std::vector<RoomBenchmarkScore> scores;
    const std::size_t total = 2 * options_.maps.size();
    std::size_t done = 0;
    if (!options_.imageDir.empty())
        fs::create_directories(options_.imageDir);
    // Every method single-threaded (OpenCV would otherwise parallelise some of its calls).
    const int threadsBefore = cv::getNumThreads();
    cv::setNumThreads(1);
    struct RestoreThreads {
        int n;
        ~RestoreThreads() { cv::setNumThreads(n); }
    } restore{threadsBefore};
    // One segmenter per variant for the whole run: it keeps its scratch images between calls,
    // as an application that segments its maps again and again would.
    const RoomSegmenter virtualDoor(options_.virtualDoor);
    const RoomSegmenter virtualDoorPaper(options_.virtualDoorPaper);
    for (const std::string& base : options_.maps) {
        const std::string dir = options_.dataDir + "/";
        const GroundTruthRooms truth =
            groundTruthRooms(readGrey(dir + base + "_gt_segmentation.png"));
        const cv::Mat baseFree = freeOf(readGrey(dir + base + ".png"));
        const std::vector<LabelBoundaryDoor> trueDoors = labelBoundaryDoors(truth.labels, baseFree);
        for (const bool furnished : {false, true}) {
            const std::string name = furnished ? base + "_furnitures" : base;
            if (progress)
                progress(done, total, name);
            ++done;
            const cv::Mat free = furnished ? freeOf(readGrey(dir + name + ".png")) : baseFree;
            const mrpt::maps::COccupancyGridMap2D grid = gridOf(free);
            for (const std::string& method : options_.methods) {
                std::vector<double> seconds;
                cv::Mat labels;
                RoomSegmenter::Result topo;
                for (int k = 0; k < options_.repeats; ++k) {
                    const auto t0 = std::chrono::steady_clock::now();
                    if (method == "vdoor" || method == "vdoor-paper") {
                        topo = (method == "vdoor" ? virtualDoor : virtualDoorPaper)
                                   .segment(grid, {}, name);
                    } else if (method == "morph") {
                        labels = MorphologicalSegmentation().segment(free, kResolution);
                    } else {
                        labels = DistanceSegmentation().segment(free, kResolution);
                    }
                    seconds.push_back(
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
                            .count());
                }
                const bool virtualDoor = method == "vdoor" || method == "vdoor-paper";
                if (virtualDoor)
                    labels = scoredLabels(topo.map, free);

                RoomBenchmarkScore s;
                s.map = name;
                s.furnished = furnished;
                s.method = method;
                s.pr = bormannPrecisionRecall(truth, labels);
                s.segments = countSegments(labels);
                s.groundTruthRooms = truth.count;
                const auto virtualDoors = labelBoundaryDoors(doorMetricSegmentLabels(labels), free);
                s.doors = matchDoors(virtualDoors, trueDoors, 10.0);
                s.doors1m = matchDoors(virtualDoors, trueDoors, 20.0);
                s.seconds = median(seconds);
                s.minSeconds = *std::min_element(seconds.begin(), seconds.end());
                scores.push_back(s);
                if (!options_.imageDir.empty()) {
                    const cv::Mat picture = renderLabelImage(labels, free, trueDoors, virtualDoors);
                    cv::imwrite(options_.imageDir + "/" + name + "." + method + ".png", picture);
                    if (virtualDoor) {
                        cv::imwrite(options_.imageDir + "/" + name + "." + method + ".steps.png",
                                    renderDiagnostics(topo, free));
                    }
                }
            }
        }
    }
    return scores;
}

std::vector<RoomBenchmarkSummary> RoomBenchmark::summarize(
    const std::vector<RoomBenchmarkScore>& scores) {
    std::vector<std::string> methods;
    for (const auto& s : scores) {
        if (std::find(methods.begin(), methods.end(), s.method) == methods.end())
            methods.push_back(s.method);
    }
    std::vector<RoomBenchmarkSummary> out;
    for (const std::string& method : methods) {
        for (const std::string group : {"unfurnished", "furnished", "all"}) {
            RoomBenchmarkSummary m;
            m.method = method;
            m.group = group;
            std::vector<const RoomBenchmarkScore*> in;
            for (const auto& s : scores) {
                if (s.method == method && (group == "all" || s.furnished == (group == "furnished")))
                    in.push_back(&s);
            }
            if (in.empty())
                continue;
            m.maps = static_cast<int>(in.size());
            const double n = static_cast<double>(in.size());
            int precisionMaps = 0, recallMaps = 0;
            for (const auto* s : in) {
                m.recallMean += s->pr.recall / n;
                m.precisionMean += s->pr.precision / n;
                m.recallPixels += s->pr.recallPixels / n;
                m.precisionPixels += s->pr.precisionPixels / n;
                m.secondsMean += s->seconds / n;
                m.minSecondsMean += s->minSeconds / n;
                m.secondsMax = std::max(m.secondsMax, s->seconds);
                m.segments += s->segments;
                m.groundTruthRooms += s->groundTruthRooms;
                for (auto [pooled, own] :
                     {std::pair{&m.doors, &s->doors}, std::pair{&m.doors1m, &s->doors1m}}) {
                    pooled->virtualDoors += own->virtualDoors;
                    pooled->matchedVirtual += own->matchedVirtual;
                    pooled->trueDoors += own->trueDoors;
                    pooled->matchedTrue += own->matchedTrue;
                }
                if (s->doors.virtualDoors > 0) {
                    m.doorPrecisionMeanOfMaps +=
                        ratio(s->doors.matchedVirtual, s->doors.virtualDoors);
                    ++precisionMaps;
                }
                if (s->doors.trueDoors > 0) {
                    m.doorRecallMeanOfMaps += ratio(s->doors.matchedTrue, s->doors.trueDoors);
                    ++recallMaps;
                }
            }
            if (precisionMaps > 0)
                m.doorPrecisionMeanOfMaps /= precisionMaps;
            if (recallMaps > 0)
                m.doorRecallMeanOfMaps /= recallMaps;
            for (const auto* s : in) {
                m.recallSd += (s->pr.recall - m.recallMean) * (s->pr.recall - m.recallMean) / n;
                m.precisionSd +=
                    (s->pr.precision - m.precisionMean) * (s->pr.precision - m.precisionMean) / n;
            }
            m.recallSd = std::sqrt(m.recallSd);
            m.precisionSd = std::sqrt(m.precisionSd);
            out.push_back(m);
        }
    }
    return out;
}

std::string RoomBenchmark::table(const std::vector<RoomBenchmarkScore>& scores,
                                 const std::vector<RoomBenchmarkSummary>& summary) {
    std::ostringstream o;
    char buf[512];
    o << "| map | method | recall % | precision % | segments / GT | door P % | door R % | time s "
         "|\n"
      << "|---|---|---|---|---|---|---|---|\n";
    for (const auto& s : scores) {
        std::snprintf(buf, sizeof buf,
                      "| %s | %s | %s | %s | %d / %d | %s (%zu/%zu) | %s (%zu/%zu) | %.3f |\n",
                      s.map.c_str(), s.method.c_str(), pct(s.pr.recall).c_str(),
                      pct(s.pr.precision).c_str(), s.segments, s.groundTruthRooms,
                      pct(ratio(s.doors.matchedVirtual, s.doors.virtualDoors)).c_str(),
                      s.doors.matchedVirtual, s.doors.virtualDoors,
                      pct(ratio(s.doors.matchedTrue, s.doors.trueDoors)).c_str(),
                      s.doors.matchedTrue, s.doors.trueDoors, s.seconds);
        o << buf;
    }
    o << "\n| method | maps | recall (mean ± sd) | precision (mean ± sd) | recall px-weighted | "
         "precision px-weighted | runtime s: median-of-repeats, mean / max (mean of min) | "
         "segments / GT rooms (sum) | door P (pooled) | door R (pooled) | door P / R (mean of "
         "maps) "
         "| door P / R at 1.0 m (pooled) |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& m : summary) {
        std::snprintf(buf, sizeof buf,
                      "| %s | %s | %s ± %s %% | %s ± %s %% | %s %% | %s %% | %.3f / %.3f (%.3f) | "
                      "%d / %d | %s %% (%zu/%zu) | "
                      "%s %% (%zu/%zu) | %s / %s %% | %s / %s %% |\n",
                      m.method.c_str(), m.group.c_str(), pct(m.recallMean).c_str(),
                      pct(m.recallSd).c_str(), pct(m.precisionMean).c_str(),
                      pct(m.precisionSd).c_str(), pct(m.recallPixels).c_str(),
                      pct(m.precisionPixels).c_str(), m.secondsMean, m.secondsMax, m.minSecondsMean,
                      m.segments, m.groundTruthRooms,
                      pct(ratio(m.doors.matchedVirtual, m.doors.virtualDoors)).c_str(),
                      m.doors.matchedVirtual, m.doors.virtualDoors,
                      pct(ratio(m.doors.matchedTrue, m.doors.trueDoors)).c_str(),
                      m.doors.matchedTrue, m.doors.trueDoors,
                      pct(m.doorPrecisionMeanOfMaps).c_str(), pct(m.doorRecallMeanOfMaps).c_str(),
                      pct(ratio(m.doors1m.matchedVirtual, m.doors1m.virtualDoors)).c_str(),
                      pct(ratio(m.doors1m.matchedTrue, m.doors1m.trueDoors)).c_str());
        o << buf;
    }
    return o.str();
}

std::string RoomBenchmark::json(const std::vector<RoomBenchmarkScore>& scores,
                                const std::vector<RoomBenchmarkSummary>& summary,
                                const RoomBenchmarkOptions& options) {
    const auto doorCounts = [](const DoorMatchCounts& d) {
        return io::Json{{"virtual_doors", d.virtualDoors},
                        {"matched_virtual", d.matchedVirtual},
                        {"true_doors", d.trueDoors},
                        {"matched_true", d.matchedTrue},
                        {"precision", ratio(d.matchedVirtual, d.virtualDoors)},
                        {"recall", ratio(d.matchedTrue, d.trueDoors)}};
    };
    io::Json maps = io::Json::array();
    for (const auto& s : scores) {
        maps.push_back({{"map", s.map},
                        {"furnished", s.furnished},
                        {"method", s.method},
                        {"recall", s.pr.recall},
                        {"precision", s.pr.precision},
                        {"recall_px_weighted", s.pr.recallPixels},
                        {"precision_px_weighted", s.pr.precisionPixels},
                        {"segments", s.segments},
                        {"ground_truth_rooms", s.groundTruthRooms},
                        {"doors_0.5m", doorCounts(s.doors)},
                        {"doors_1.0m", doorCounts(s.doors1m)},
                        {"seconds_median", s.seconds},
                        {"seconds_min", s.minSeconds}});
    }
    io::Json methods = io::Json::array();
    for (const auto& m : summary) {
        methods.push_back({{"method", m.method},
                           {"group", m.group},
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
                           {"segments", m.segments},
                           {"ground_truth_rooms", m.groundTruthRooms},
                           {"doors_0.5m_pooled", doorCounts(m.doors)},
                           {"doors_1.0m_pooled", doorCounts(m.doors1m)},
                           {"door_precision_mean_of_maps", m.doorPrecisionMeanOfMaps},
                           {"door_recall_mean_of_maps", m.doorRecallMeanOfMaps}});
    }
    return io::formatJson({{"benchmark", "B4 room segmentation"},
                           {"data_dir", options.dataDir},
                           {"repeats", options.repeats},
                           {"resolution_m", kResolution},
                           {"maps", maps},
                           {"summary", methods}});
}

}  // namespace toposlam::rooms
