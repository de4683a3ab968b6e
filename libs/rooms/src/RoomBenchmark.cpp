#include <toposlam/io/CpuTime.h>
#include <toposlam/rooms/DistanceSegmentation.h>
#include <toposlam/rooms/MorphologicalSegmentation.h>
#include <toposlam/rooms/RoomBenchmark.h>
#include <toposlam/rooms/TopologicalMapRendering.h>

#include "GridRay.h"

#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <tuple>

namespace toposlam::rooms {

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v[v.size() / 2];
}

// Every method single-threaded while a benchmark runs (OpenCV would otherwise parallelise some
// of its calls); the previous setting comes back at the end.
struct SingleThreaded {
    int before = cv::getNumThreads();
    SingleThreaded() { cv::setNumThreads(1); }
    ~SingleThreaded() { cv::setNumThreads(before); }
};

void add(DoorMatchCounts& pooled, const DoorMatchCounts& own) {
    pooled.virtualDoors += own.virtualDoors;
    pooled.matchedVirtual += own.matchedVirtual;
    pooled.trueDoors += own.trueDoors;
    pooled.matchedTrue += own.matchedTrue;
}

RoomBenchmarkSummary summarizeGroup(const std::vector<const RoomBenchmarkScore*>& in) {
    RoomBenchmarkSummary m;
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
        m.cpuSecondsMean += s->cpuSeconds / n;
        m.secondsMax = std::max(m.secondsMax, s->seconds);
        m.segments += s->segments;
        m.groundTruthRooms += s->groundTruthRooms;
        add(m.doors, s->doors);
        add(m.doors1m, s->doors1m);
        if (s->doors.virtualDoors > 0) {
            m.doorPrecisionMeanOfMaps += s->doors.precision();
            ++precisionMaps;
        }
        if (s->doors.trueDoors > 0) {
            m.doorRecallMeanOfMaps += s->doors.recall();
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
    return m;
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

RoomBenchmark::RoomBenchmark(RoomBenchmarkOptions options)
    : options_(std::move(options)),
      virtualDoor_(options_.virtualDoor),
      virtualDoorPaper_(options_.virtualDoorPaper) {
    if (options_.methods.empty())
        options_.methods = methodNames();
    if (options_.maps.empty())
        options_.maps = benchmarkMaps();
    if (options_.rotationsDeg.empty())
        options_.rotationsDeg = {0};
    for (const std::string& m : options_.methods) {
        if (std::find(methodNames().begin(), methodNames().end(), m) == methodNames().end()) {
            throw std::invalid_argument("unknown method '" + m +
                                        "' (vdoor, vdoor-paper, morph, dist)");
        }
    }
    for (const double a : options_.rotationsDeg) {
        if (!std::isfinite(a) || a < -360 || a > 360)
            throw std::invalid_argument("rotation angles must be in [-360, 360] degrees");
    }
    if (!std::isfinite(options_.cellSize) || options_.cellSize < 0)
        throw std::invalid_argument("the cell size must be a length >= 0 m");
    options_.repeats = std::max(1, options_.repeats);
}

std::vector<RoomBenchmarkCase> RoomBenchmark::atCellSize(
    std::vector<RoomBenchmarkCase> cases) const {
    if (options_.cellSize > 0) {
        for (RoomBenchmarkCase& c : cases)
            c = caseAtCellSize(c, options_.cellSize);
    }
    return cases;
}

cv::Mat RoomBenchmark::scoredLabels(const TopologicalMap& map, const cv::Mat& freeImage) {
    cv::Mat labels = map.labels.clone();
    labels.setTo(kUnassignedLabel, (labels == 0) & (freeImage != 0));
    return labels;
}

std::vector<RoomBenchmarkScore> RoomBenchmark::run(const io::ProgressCallback& progress) const {
    return runCases(
        options_.maps.size(),
        [&](std::size_t i) {
            return atCellSize(
                bormannCases(options_.dataDir, options_.maps[i], options_.rotationsDeg));
        },
        progress);
}

std::vector<RoomBenchmarkScore> RoomBenchmark::runCases(
    std::size_t count, const std::function<std::vector<RoomBenchmarkCase>(std::size_t)>& makeCases,
    const io::ProgressCallback& progress) const {
    const SingleThreaded singleThreaded;
    if (!options_.imageDir.empty())
        std::filesystem::create_directories(options_.imageDir);
    std::vector<RoomBenchmarkScore> scores;
    for (std::size_t i = 0; i < count; ++i) {
        for (const RoomBenchmarkCase& c : makeCases(i)) {
            const auto own = score(c);
            scores.insert(scores.end(), own.begin(), own.end());
        }
        if (progress)
            progress(static_cast<double>(i + 1) / static_cast<double>(count), i + 1);
    }
    return scores;
}

std::vector<RoomBenchmarkScore> RoomBenchmark::score(const RoomBenchmarkCase& c) const {
    std::vector<RoomBenchmarkScore> scores;
    const double resolution = c.grid.getResolution();
    for (const std::string& method : options_.methods) {
        const bool virtualDoor = method == "vdoor" || method == "vdoor-paper";
        std::vector<double> seconds, cpu;
        cv::Mat labels;
        RoomSegmenter::Result topo;
        for (int k = 0; k < options_.repeats; ++k) {
            const auto t0 = std::chrono::steady_clock::now();
            const double cpu0 = io::threadCpuSeconds();
            if (virtualDoor) {
                topo = (method == "vdoor" ? virtualDoor_ : virtualDoorPaper_)
                           .segment(c.grid, c.trajectory, c.name());
            } else if (method == "morph") {
                labels = MorphologicalSegmentation().segment(c.inputFree, resolution);
            } else {
                labels = DistanceSegmentation().segment(c.inputFree, resolution);
            }
            cpu.push_back(io::threadCpuSeconds() - cpu0);
            seconds.push_back(
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
        if (virtualDoor)
            labels = scoredLabels(topo.map, c.inputFree);
        if (c.toTruthFrame)
            labels = c.toTruthFrame(labels);

        RoomBenchmarkScore s;
        s.dataset = c.dataset;
        s.map = c.map;
        s.furnished = c.furnished;
        s.rotationDeg = c.rotationDeg;
        s.method = method;
        s.pr = bormannPrecisionRecall(c.truth, labels);
        if (!c.openFloor.labels.empty()) {
            cv::Mat openLabels = labels.clone();
            openLabels.setTo(0, (c.truth.labels != 0) & (c.openFloor.labels == 0));
            s.openFloor = bormannPrecisionRecall(c.openFloor, openLabels);
        }
        s.segments = countSegments(labels);
        s.groundTruthRooms = c.truth.count;
        const auto virtualDoors = labelBoundaryDoors(doorMetricSegmentLabels(labels), c.scoredFree);
        const double truthResolution = c.truthResolution > 0 ? c.truthResolution : resolution;
        s.doors = matchDoors(virtualDoors, c.trueDoors, detail::toCells(0.5, truthResolution));
        s.doors1m = matchDoors(virtualDoors, c.trueDoors, detail::toCells(1.0, truthResolution));
        s.seconds = median(seconds);
        s.minSeconds = *std::min_element(seconds.begin(), seconds.end());
        s.cpuSeconds = median(cpu);
        scores.push_back(s);
        if (!options_.imageDir.empty()) {
            const std::string stem =
                options_.imageDir + "/" + c.dataset + "." + c.name() + "." + method;
            cv::imwrite(stem + ".png",
                        renderLabelImage(labels, c.scoredFree, c.trueDoors, virtualDoors));
            if (virtualDoor)
                cv::imwrite(stem + ".steps.png", renderDiagnostics(topo, c.inputFree));
        }
    }
    return scores;
}

std::vector<RoomBenchmarkSummary> RoomBenchmark::summarize(
    const std::vector<RoomBenchmarkScore>& scores) {
    // Keys in order of first appearance.
    std::vector<std::tuple<std::string, std::string>> datasetMethods;
    std::vector<double> angles;
    for (const auto& s : scores) {
        const auto key = std::make_tuple(s.dataset, s.method);
        if (std::find(datasetMethods.begin(), datasetMethods.end(), key) == datasetMethods.end())
            datasetMethods.push_back(key);
        if (std::find(angles.begin(), angles.end(), s.rotationDeg) == angles.end())
            angles.push_back(s.rotationDeg);
    }
    std::vector<std::optional<double>> angleGroups(angles.begin(), angles.end());
    if (angles.size() > 1)
        angleGroups.push_back(std::nullopt);
    std::vector<RoomBenchmarkSummary> out;
    for (const auto& [dataset, method] : datasetMethods) {
        for (const auto& angle : angleGroups) {
            for (const std::string group : {"unfurnished", "furnished", "all"}) {
                std::vector<const RoomBenchmarkScore*> in;
                for (const auto& s : scores) {
                    if (s.dataset == dataset && s.method == method &&
                        (!angle || s.rotationDeg == *angle) &&
                        (group == "all" || s.furnished == (group == "furnished"))) {
                        in.push_back(&s);
                    }
                }
                if (in.empty())
                    continue;
                RoomBenchmarkSummary m = summarizeGroup(in);
                m.dataset = dataset;
                m.method = method;
                m.group = group;
                m.rotationDeg = angle;
                out.push_back(m);
            }
        }
    }
    return out;
}

}  // namespace toposlam::rooms
