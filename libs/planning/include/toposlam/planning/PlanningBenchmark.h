#pragma once
// Benchmark B5 (shared/BENCHMARKS.md): room-to-room planning on segmented maps. For a sample
// of room pairs of each map, the room-graph planner (RoomToRoomPlanner: door route + OMPL per
// leg) and plain OMPL from anchor to anchor (same planner, same total time budget) are run and
// compared with the shortest 8-connected grid path (ShortestGridPath) on the same inflated grid:
// success rate (a collision-free path found), path length relative to A*, time per query.
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <toposlam/planning/OmplPathPlanner.h>
#include <toposlam/rooms/TopologicalMap.h>

#include <string>
#include <vector>

namespace toposlam::planning {

struct PlanningBenchmarkOptions {
    double robotRadius = 0.25;   ///< m
    double freeThreshold = 0.6;  ///< p(free) above which a cell is free
    OmplPlannerOptions ompl;     ///< per leg for the room planner; x legs in total for plain OMPL
    int maxPairsPerMap = 30;     ///< room pairs sampled per map (fixed seed); 0 = all
};

/// One query: one method between two rooms.
struct PlanningQuery {
    std::string map, method;
    int fromRoom = 0, toRoom = 0;
    bool solved = false;
    double length = 0;           ///< m
    double referenceLength = 0;  ///< A* length, m
    double seconds = 0;
};

struct PlanningSummary {
    std::string method;
    int queries = 0, solved = 0;
    double lengthRatioMedian = 0, lengthRatioP95 = 0;  ///< length / A*, solved queries
    double msMedian = 0, msP95 = 0;
};

class PlanningBenchmark {
  public:
    explicit PlanningBenchmark(PlanningBenchmarkOptions options);

    /// Runs every method on sampled room pairs of one map (rooms segmented from `grid`). Pairs
    /// that A* cannot connect (no traversable way for the robot) are not queried.
    std::vector<PlanningQuery> run(const std::string& mapName,
                                   const mrpt::maps::COccupancyGridMap2D& grid,
                                   const rooms::TopologicalMap& rooms) const;

    static std::vector<PlanningSummary> summarize(const std::vector<PlanningQuery>& queries);
    static std::string table(const std::vector<PlanningSummary>& summary);
    static std::string json(const std::vector<PlanningQuery>& queries,
                            const std::vector<PlanningSummary>& summary,
                            const PlanningBenchmarkOptions& options);

  private:
    PlanningBenchmarkOptions options_;
};

}  // namespace toposlam::planning
