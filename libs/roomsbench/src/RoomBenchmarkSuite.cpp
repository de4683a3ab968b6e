#include <toposlam/roomsbench/GeneratedRoomCases.h>
#include <toposlam/roomsbench/RoomBenchmarkSuite.h>

#include <toposlam/io/JsonFile.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <stdexcept>

namespace toposlam::roomsbench {

RoomBenchmarkSuiteResult runRoomBenchmarkSuite(const RoomBenchmarkSuiteOptions& options,
                                               const io::ProgressCallback& progress) {
    const rooms::RoomBenchmark bench(options.bench);
    const auto& o = bench.options();
    const std::size_t bormann = options.bormann ? o.maps.size() : 0;
    const std::size_t generated = options.generatedSeeds.size();
    const std::size_t flats = options.flatSeeds.size();
    const std::size_t rings = options.ringSeeds.size();
    const std::size_t endToEnd = options.endToEndSeeds.size() + options.endToEndBormannMaps.size() +
                                 options.endToEndRingSeeds.size();
    const std::size_t total = bormann + generated + flats + rings + endToEnd;
    if (total == 0)
        throw std::invalid_argument(
            "nothing to run: no Bormann map, generated plan or end-to-end plan");
    if (endToEnd > 0 && options.endToEnd.slamConfig == nullptr)
        throw std::invalid_argument("the end-to-end set needs a SLAM configuration");
    // Each set reports its part of the whole.
    auto part = [&](std::size_t before, std::size_t count) -> io::ProgressCallback {
        if (!progress)
            return {};
        return [&progress, before, count, total](double fraction, std::size_t) {
            const double done = static_cast<double>(before) + fraction * static_cast<double>(count);
            progress(done / static_cast<double>(total), static_cast<std::size_t>(done));
        };
    };
    RoomBenchmarkSuiteResult result;
    auto append = [&](const std::vector<rooms::RoomBenchmarkScore>& s) {
        result.scores.insert(result.scores.end(), s.begin(), s.end());
    };
    if (bormann > 0)
        append(bench.run(part(0, bormann)));
    // A generated set: its plans at every angle, in coarser cells when asked.
    auto runGenerated = [&](const std::vector<unsigned>& seeds, simulation::BuildingStyle style,
                            std::size_t before) {
        append(bench.runCases(
            seeds.size(),
            [&](std::size_t i) {
                return bench.atCellSize(generatedCases(seeds[i], o.rotationsDeg, style));
            },
            part(before, seeds.size())));
    };
    runGenerated(options.generatedSeeds, simulation::BuildingStyle::Office, bormann);
    runGenerated(options.flatSeeds, simulation::BuildingStyle::Flat, bormann + generated);
    runGenerated(options.ringSeeds, simulation::BuildingStyle::Ring, bormann + generated + flats);
    if (endToEnd > 0) {
        const auto plans = plansToTour(options.endToEndSeeds, options.endToEndBormannMaps,
                                       o.dataDir, options.endToEndRingSeeds);
        append(bench.runCases(
            plans.size(),
            [&](std::size_t i) {
                EndToEndRecord record{plans[i].name, {}};
                auto slam = endToEndCase(plans[i], options.endToEnd, record.run);
                result.endToEnd.push_back(record);
                std::vector<rooms::RoomBenchmarkCase> cases;
                cases.push_back(drawnPlanCase(plans[i]));
                cases.push_back(std::move(slam));
                return cases;
            },
            part(bormann + generated + flats + rings, endToEnd)));
    }
    result.summary = rooms::RoomBenchmark::summarize(result.scores);
    return result;
}

namespace {
// Mean of `roomRecall` over the ground-truth rooms not in `outOfView` (labels from 1).
double recallInView(const std::vector<double>& roomRecall, const std::vector<int>& outOfView) {
    double sum = 0;
    std::size_t rooms = 0;
    for (std::size_t g = 0; g < roomRecall.size(); ++g) {
        if (std::find(outOfView.begin(), outOfView.end(), static_cast<int>(g + 1)) ==
            outOfView.end()) {
            sum += roomRecall[g];
            ++rooms;
        }
    }
    return rooms > 0 ? sum / static_cast<double>(rooms) : 0;
}

double openFloorRecallInView(const rooms::RoomBenchmarkScore& score,
                             const std::vector<int>& outOfView) {
    return score.openFloor ? recallInView(score.openFloor->roomRecall, outOfView) : 0;
}

// The drawn plan's score beside a SLAM grid's (same plan, same method), or null.
const rooms::RoomBenchmarkScore* drawnScoreOf(const RoomBenchmarkSuiteResult& result,
                                              const rooms::RoomBenchmarkScore& slam) {
    const auto drawn = std::find_if(
        result.scores.begin(), result.scores.end(), [&](const rooms::RoomBenchmarkScore& s) {
            return s.dataset == "drawn" && s.map == slam.map && s.method == slam.method;
        });
    return drawn == result.scores.end() ? nullptr : &*drawn;
}

// Recall of drawn plan and SLAM grid over the rooms the tour had in view, then over their open
// floor only, per plan and method: what the segmentation loses on a SLAM grid, apart from rooms
// no robot on that tour saw and from the one-cell quantisation of walls and furniture.
std::string inViewTable(const RoomBenchmarkSuiteResult& result) {
    std::string text =
        "\n| plan | method | GT rooms out of the tour's view | recall over the rooms in view: "
        "drawn | SLAM | ... over their open floor: drawn | SLAM |\n|---|---|---|---|---|---|---|\n";
    // method -> drawn, SLAM, open floor drawn, open floor SLAM, plans
    std::map<std::string, std::array<double, 5>> pooled;
    char buf[320];
    for (const auto& e : result.endToEnd) {
        for (const auto& slam : result.scores) {
            if (slam.dataset != "slam" || slam.map != e.map)
                continue;
            const rooms::RoomBenchmarkScore* drawn = drawnScoreOf(result, slam);
            if (!drawn)
                continue;
            const auto& out = e.run.roomsOutOfView;
            const std::array<double, 4> r = {
                recallInView(drawn->pr.roomRecall, out), recallInView(slam.pr.roomRecall, out),
                openFloorRecallInView(*drawn, out), openFloorRecallInView(slam, out)};
            auto& p = pooled[slam.method];
            for (std::size_t k = 0; k < r.size(); ++k)
                p[k] += r[k];
            p[4] += 1;
            std::snprintf(buf, sizeof buf,
                          "| %s | %s | %zu of %d | %.1f %% | %.1f %% | %.1f %% | %.1f %% |\n",
                          e.map.c_str(), slam.method.c_str(), out.size(), slam.groundTruthRooms,
                          100 * r[0], 100 * r[1], 100 * r[2], 100 * r[3]);
            text += buf;
        }
    }
    for (const auto& [method, p] : pooled) {
        std::snprintf(buf, sizeof buf, "| mean | %s | | %.1f %% | %.1f %% | %.1f %% | %.1f %% |\n",
                      method.c_str(), 100 * p[0] / p[4], 100 * p[1] / p[4], 100 * p[2] / p[4],
                      100 * p[3] / p[4]);
        text += buf;
    }
    return text;
}

// Precision of drawn plan and SLAM grid with and without the segment of free space no room
// took (65280), per plan and method: on a SLAM grid that one segment, mostly free cells outside
// every ground-truth room, is most of what precision loses.
std::string unassignedTable(const RoomBenchmarkSuiteResult& result) {
    std::string text =
        "\n| plan | method | precision: drawn | SLAM | unassigned free px: drawn | SLAM | "
        "precision of the rooms: drawn | SLAM |\n|---|---|---|---|---|---|---|---|\n";
    std::map<std::string, std::array<double, 5>> pooled;  // method -> 4 precisions, plans
    char buf[320];
    for (const auto& slam : result.scores) {
        if (slam.dataset != "slam")
            continue;
        const rooms::RoomBenchmarkScore* drawn = drawnScoreOf(result, slam);
        if (!drawn)
            continue;
        auto& p = pooled[slam.method];
        p[0] += drawn->pr.precision;
        p[1] += slam.pr.precision;
        p[2] += drawn->pr.precisionOfRooms;
        p[3] += slam.pr.precisionOfRooms;
        p[4] += 1;
        std::snprintf(buf, sizeof buf,
                      "| %s | %s | %.1f %% | %.1f %% | %zu | %zu | %.1f %% | %.1f %% |\n",
                      slam.map.c_str(), slam.method.c_str(), 100 * drawn->pr.precision,
                      100 * slam.pr.precision, drawn->pr.unassignedPixels, slam.pr.unassignedPixels,
                      100 * drawn->pr.precisionOfRooms, 100 * slam.pr.precisionOfRooms);
        text += buf;
    }
    for (const auto& [method, p] : pooled) {
        std::snprintf(buf, sizeof buf,
                      "| mean | %s | %.1f %% | %.1f %% | | | %.1f %% | %.1f %% |\n", method.c_str(),
                      100 * p[0] / p[4], 100 * p[1] / p[4], 100 * p[2] / p[4], 100 * p[3] / p[4]);
        text += buf;
    }
    return text;
}
}  // namespace

std::string suiteTable(const RoomBenchmarkSuiteResult& result) {
    std::string text = rooms::RoomBenchmark::table(result.scores, result.summary);
    if (result.endToEnd.empty())
        return text;
    text +=
        "\n| plan | scans | tour m | SLAM s | SLAM -> plan (x m, y m, yaw °) | trajectory RMSE m "
        "|\n"
        "|---|---|---|---|---|---|\n";
    char buf[256];
    for (const auto& e : result.endToEnd) {
        std::snprintf(buf, sizeof buf, "| %s | %zu | %.0f | %.1f | %.2f, %.2f, %.1f | %.3f |\n",
                      e.map.c_str(), e.run.scans, e.run.tourLength, e.run.slamSeconds,
                      e.run.slamToPlan.x, e.run.slamToPlan.y, e.run.slamToPlan.phi * 180 / M_PI,
                      e.run.alignmentRmse);
        text += buf;
    }
    text += inViewTable(result);
    text += unassignedTable(result);
    return text;
}

std::string suiteJson(const RoomBenchmarkSuiteResult& result,
                      const RoomBenchmarkSuiteOptions& options) {
    io::Json j = io::parseJson(
        rooms::RoomBenchmark::json(result.scores, result.summary, options.bench), "B4 report");
    j["generated_seeds"] = options.generatedSeeds;
    j["flat_seeds"] = options.flatSeeds;
    j["ring_seeds"] = options.ringSeeds;
    j["end_to_end"] = io::Json::array();
    for (const auto& e : result.endToEnd) {
        j["end_to_end"].push_back(
            {{"map", e.map},
             {"scans", e.run.scans},
             {"tour_length_m", e.run.tourLength},
             {"slam_seconds", e.run.slamSeconds},
             {"slam_to_plan", {e.run.slamToPlan.x, e.run.slamToPlan.y, e.run.slamToPlan.phi}},
             {"alignment_rmse_m", e.run.alignmentRmse},
             {"ground_truth_rooms_out_of_view", e.run.roomsOutOfView}});
    }
    return io::formatJson(j);
}

}  // namespace toposlam::roomsbench
