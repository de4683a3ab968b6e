#include <toposlam/io/JsonFile.h>
#include <toposlam/planning/PlanningBenchmark.h>
#include <toposlam/planning/RoomToRoomPlanner.h>
#include <toposlam/planning/ShortestGridPath.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <sstream>

namespace toposlam::planning {

namespace {

double percentile(std::vector<double> v, double p) {
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    const auto k = static_cast<std::size_t>(p * static_cast<double>(v.size() - 1) + 0.5);
    return v[std::min(k, v.size() - 1)];
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

PlanningBenchmark::PlanningBenchmark(PlanningBenchmarkOptions options)
    : options_(std::move(options)) {
    options_.ompl.validate();
}

std::vector<PlanningQuery> PlanningBenchmark::run(const std::string& mapName,
                                                  const mrpt::maps::COccupancyGridMap2D& grid,
                                                  const rooms::TopologicalMap& rooms) const {
    const TraversabilityGrid traversable(grid, options_.robotRadius, options_.freeThreshold);
    ShortestGridPath astar(traversable);
    RoomToRoomPlanner roomPlanner(rooms, traversable, options_.ompl);

    std::vector<std::pair<int, int>> pairs;
    for (const auto& a : rooms.rooms) {
        for (const auto& b : rooms.rooms) {
            if (a.id < b.id)
                pairs.emplace_back(a.id, b.id);
        }
    }
    if (options_.maxPairsPerMap > 0 &&
        pairs.size() > static_cast<std::size_t>(options_.maxPairsPerMap)) {
        std::mt19937 rng(12345);  // the same sample on every run
        std::shuffle(pairs.begin(), pairs.end(), rng);
        pairs.resize(static_cast<std::size_t>(options_.maxPairsPerMap));
        std::sort(pairs.begin(), pairs.end());
    }

    std::vector<PlanningQuery> queries;
    for (const auto& [from, to] : pairs) {
        const auto& a = *rooms.room(from);
        const auto& b = *rooms.room(to);
        const auto reference = astar.plan(a.anchor, b.anchor);
        if (!reference)
            continue;

        PlanningQuery q{mapName, "room graph + OMPL", from, to};
        q.referenceLength = reference->length;
        const RoomPath path = roomPlanner.plan(from, to);
        q.solved = path.solved;
        q.length = path.length;
        q.seconds = path.seconds;
        queries.push_back(q);

        // Plain OMPL gets the same total budget as the room planner's legs.
        OmplPlannerOptions direct = options_.ompl;
        const std::size_t legs = path.solved ? path.route.waypoints.size() - 1 : 1;
        direct.timeLimit *= static_cast<double>(std::max<std::size_t>(1, legs));
        OmplPathPlanner plain(traversable, direct);
        PlanningQuery d{mapName, "OMPL " + options_.ompl.planner, from, to};
        d.referenceLength = reference->length;
        const auto t0 = std::chrono::steady_clock::now();
        const auto points = plain.plan(a.anchor, b.anchor);
        d.seconds = secondsSince(t0);
        d.solved = points.has_value();
        d.length = points ? polylineLength(*points) : 0;
        queries.push_back(d);

        PlanningQuery g{mapName, "grid A* (reference)", from, to};
        g.referenceLength = g.length = reference->length;
        g.solved = true;
        const auto t1 = std::chrono::steady_clock::now();
        astar.plan(a.anchor, b.anchor);
        g.seconds = secondsSince(t1);
        queries.push_back(g);
    }
    return queries;
}

std::vector<PlanningSummary> PlanningBenchmark::summarize(
    const std::vector<PlanningQuery>& queries) {
    std::vector<PlanningSummary> out;
    for (const auto& q : queries) {
        if (std::none_of(out.begin(), out.end(),
                         [&](const auto& s) { return s.method == q.method; })) {
            out.push_back({q.method});
        }
    }
    for (auto& s : out) {
        std::vector<double> ratios, ms;
        for (const auto& q : queries) {
            if (q.method != s.method)
                continue;
            ++s.queries;
            ms.push_back(1e3 * q.seconds);
            if (!q.solved)
                continue;
            ++s.solved;
            ratios.push_back(q.length / q.referenceLength);
        }
        s.lengthRatioMedian = percentile(ratios, 0.5);
        s.lengthRatioP95 = percentile(ratios, 0.95);
        s.msMedian = percentile(ms, 0.5);
        s.msP95 = percentile(ms, 0.95);
    }
    return out;
}

std::string PlanningBenchmark::table(const std::vector<PlanningSummary>& summary) {
    std::ostringstream out;
    out << "| method | queries | success | length / A* (median, p95) | ms per query (median, p95) "
           "|\n"
        << "|---|---|---|---|---|\n";
    char buf[256];
    for (const auto& s : summary) {
        std::snprintf(buf, sizeof buf, "| %s | %d | %.1f %% | %.3f, %.3f | %.2f, %.2f |\n",
                      s.method.c_str(), s.queries, s.queries ? 100.0 * s.solved / s.queries : 0.0,
                      s.lengthRatioMedian, s.lengthRatioP95, s.msMedian, s.msP95);
        out << buf;
    }
    return out.str();
}

std::string PlanningBenchmark::json(const std::vector<PlanningQuery>& queries,
                                    const std::vector<PlanningSummary>& summary,
                                    const PlanningBenchmarkOptions& options) {
    io::Json methods = io::Json::array(), results = io::Json::array();
    for (const auto& s : summary) {
        methods.push_back({{"method", s.method},
                           {"queries", s.queries},
                           {"solved", s.solved},
                           {"length_ratio_median", s.lengthRatioMedian},
                           {"length_ratio_p95", s.lengthRatioP95},
                           {"ms_median", s.msMedian},
                           {"ms_p95", s.msP95}});
    }
    for (const auto& q : queries) {
        results.push_back({{"map", q.map},
                           {"method", q.method},
                           {"from", q.fromRoom},
                           {"to", q.toRoom},
                           {"solved", q.solved},
                           {"length_m", q.length},
                           {"astar_length_m", q.referenceLength},
                           {"seconds", q.seconds}});
    }
    const io::Json settings = {{"robot_radius_m", options.robotRadius},
                               {"planner", options.ompl.planner},
                               {"time_limit_s_per_leg", options.ompl.timeLimit},
                               {"max_pairs_per_map", options.maxPairsPerMap}};
    return io::formatJson({{"benchmark", "B5 room-to-room planning"},
                           {"options", settings},
                           {"summary", methods},
                           {"queries", results}});
}

}  // namespace toposlam::planning
