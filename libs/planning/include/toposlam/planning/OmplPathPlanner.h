#pragma once
// Point-to-point geometric planning for a disc robot on a TraversabilityGrid with OMPL: the
// state space is the plane (m), a state is valid when the robot fits there, and motions are
// checked at a quarter of a cell. Any of OMPL's geometric planners can be chosen by name; the
// solution is shortened by OMPL's path simplifier.
#include <mrpt/math/TPoint2D.h>
#include <toposlam/planning/TraversabilityGrid.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace toposlam::planning {

struct OmplPlannerOptions {
    /// rrtconnect (default: fast bidirectional RRT), rrtstar, informedrrtstar, prmstar, bitstar
    std::string planner = "rrtconnect";
    double timeLimit = 1.0;  ///< s per query (per leg for RoomToRoomPlanner)
    bool simplify = true;    ///< shortcut and smooth the solution
    /// Independent solves per query, the shortest kept: a feasible planner such as RRT-Connect
    /// goes around an obstacle on a random side, which no shortcutting undoes.
    int attempts = 3;
    /// Throws std::invalid_argument for an unknown planner name, a non-positive time or
    /// attempts < 1.
    void validate() const;
};

/// The planner names OmplPlannerOptions::planner accepts.
const std::vector<std::string>& omplPlannerNames();

class OmplPathPlanner {
  public:
    OmplPathPlanner(const TraversabilityGrid& grid, const OmplPlannerOptions& options = {});
    ~OmplPathPlanner();

    /// Collision-free polyline from `from` to `to` (both must be traversable): the shortest of
    /// `attempts` solutions, or nullopt when no attempt found one within the time limit.
    std::optional<std::vector<mrpt::math::TPoint2D>> plan(const mrpt::math::TPoint2D& from,
                                                          const mrpt::math::TPoint2D& to);

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace toposlam::planning
