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
    /// Throws std::invalid_argument for an unknown planner name or a non-positive time.
    void validate() const;
};

class OmplPathPlanner {
  public:
    OmplPathPlanner(const TraversabilityGrid& grid, const OmplPlannerOptions& options = {});
    ~OmplPathPlanner();

    /// Collision-free polyline from `from` to `to` (both must be traversable), or nullopt
    /// when the planner found none within the time limit.
    std::optional<std::vector<mrpt::math::TPoint2D>> plan(const mrpt::math::TPoint2D& from,
                                                          const mrpt::math::TPoint2D& to);
    /// Shortens a valid polyline (OMPL's shortcutting) keeping it valid; returns it unchanged
    /// when simplification is off.
    std::vector<mrpt::math::TPoint2D> simplify(const std::vector<mrpt::math::TPoint2D>& path);
    /// Whether the straight motion between two points keeps the robot on traversable cells.
    bool isMotionValid(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b) const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace toposlam::planning
