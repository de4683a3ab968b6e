#pragma once
// People walking through the map while the robot records: discs that go from one random free
// place to another along clearance-keeping grid paths (GridPathPlanner), at walking speed,
// pausing a little at each place. A person's outline never overlaps an obstacle cell. People
// keep out of the robot's way: they stop rather than walk into it, walk elsewhere when it blocks
// them for two seconds, and step aside when it drives up to them (a person cornered by the
// robot may still end up within the keep-out distance).
#include <mrpt/math/TPoint2D.h>
#include <toposlam/config/Options.h>
#include <toposlam/simulation/ClearanceMap.h>
#include <toposlam/simulation/GridPathPlanner.h>
#include <toposlam/simulation/PolygonWorld.h>

#include <random>
#include <string>
#include <vector>

namespace mrpt::config {
class CConfigFileBase;
}

namespace toposlam::simulation {

/// Section [People] of config_ini/sim-office.ini.
struct PeopleOptions : public config::Options {
    std::size_t count = 0;        ///< number of people
    double radius = 0.25;         ///< m (shoulder half-width)
    double minSpeed = 0.8;        ///< m/s; each walk picks a speed in [minSpeed, maxSpeed]
    double maxSpeed = 1.3;        ///< m/s
    double maxPause = 3.0;        ///< s; pause at each destination, uniform in [0, maxPause]
    double maxTripLength = 12.0;  ///< m; destinations are at most this far (straight line)
    /// m between a person's centre and the robot's centre (robot radius + person radius + 0.1)
    double robotKeepOut = 0.6;

    void declare(config::OptionsSchema& s) override;
};

class MovingObstacles {
  public:
    /// People start at random free places at least 1 m from `robotStart`. `seed` fixes the
    /// whole simulation.
    MovingObstacles(const ClearanceMap& map, const PeopleOptions& options,
                    const mrpt::math::TPoint2D& robotStart, unsigned seed);

    /// Lets `dt` seconds pass with the robot at `robot` (world frame, m).
    void advance(double dt, const mrpt::math::TPoint2D& robot);
    /// Current people (world frame).
    const std::vector<Disc>& discs() const { return discs_; }

  private:
    struct Walker {
        std::vector<mrpt::math::TPoint2D> path;
        std::size_t next = 0;  ///< index of the path point being walked to
        double speed = 1.0;    ///< m/s
        double pause = 0;      ///< s left to wait before the next walk
        double blocked = 0;    ///< s spent waiting for the robot to make way
    };
    mrpt::math::TPoint2D randomFreePlace();
    void startWalk(std::size_t i);
    /// Moves person i away from a robot that came within the keep-out distance; false if the
    /// robot is not that close.
    bool stepAside(std::size_t i, double dt, const mrpt::math::TPoint2D& robot);

    const ClearanceMap& map_;
    PeopleOptions options_;
    GridPathPlanner planner_;
    std::mt19937 rng_;
    std::vector<std::size_t> freeCells_;  ///< cells a person fits in
    std::vector<Walker> walkers_;
    std::vector<Disc> discs_;
};

}  // namespace toposlam::simulation
