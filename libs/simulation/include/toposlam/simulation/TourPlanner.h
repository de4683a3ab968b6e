#pragma once
// An automatic robot tour over a map that visits every room-sized free area: find the areas
// (RoomSizedAreas), order them (TourOrder) by path cost, plan a clearance-keeping path between
// consecutive ones (GridPathPlanner), smooth it (PathSmoother) and drive it (MotionProfile),
// which gives the timed poses at which the laser records. Free space that runs on to the map's
// edge (the background of a drawn plan) is no room: it is left out. Then look at what that tour
// leaves unseen (TourCoverage: closets, side rooms, space behind furniture), add a stop in view of
// each unseen area, and plan the tour again over all stops.
#include <mrpt/math/TPose2D.h>
#include <toposlam/config/Options.h>
#include <toposlam/io/Trajectory.h>
#include <toposlam/simulation/ClearanceMap.h>
#include <toposlam/simulation/GridPathPlanner.h>
#include <toposlam/simulation/MotionProfile.h>
#include <toposlam/simulation/RoomSizedAreas.h>
#include <toposlam/simulation/TourCoverage.h>

#include <optional>
#include <vector>

namespace toposlam::simulation {

/// Section [Tour] of config_ini/sim-office.ini (`start` is no key: toposlam-sim --start).
struct TourOptions : public config::Options {
    double robotRadius = 0.25;        ///< m
    double safetyMargin = 0.05;       ///< m kept between the robot's outline and any obstacle
    double preferredClearance = 0.8;  ///< m; see PathCostOptions
    double clearanceWeight = 3.0;     ///< see PathCostOptions
    RoomSizedAreaOptions areas;
    double smoothingSigma = 0.3;  ///< m; see smoothPath
    bool returnToStart = true;    ///< close the loop (SLAM needs loops to be tested)
    /// Drive the closed tour this many times (needs returnToStart): a long log that keeps
    /// coming back, as a robot patrolling a building records it.
    int laps = 1;
    TourCoverageOptions coverage;
    /// Start pose (world frame); default: the centre of the largest area the tour visits,
    /// heading along the first leg.
    std::optional<mrpt::math::TPose2D> start;
    MotionOptions motion;

    PathCostOptions pathCost() const {
        return {robotRadius + safetyMargin, preferredClearance, clearanceWeight};
    }
    void declare(config::OptionsSchema& s) override;
};

struct Tour {
    std::vector<RoomSizedArea> areas;      ///< every area found, largest first
    std::vector<std::size_t> visitOrder;   ///< indices into `areas`, in visiting order
    std::vector<std::size_t> unreachable;  ///< areas the robot cannot reach from the start
    /// Areas open to the map's edge (RoomSizedArea::openToMapEdge), left out of the tour
    /// unless every area is: the free background around a drawn building is no room.
    std::vector<std::size_t> outside;
    /// Unseen by the room-sized tour (coverage.lookIntoUnseen), largest first; the final tour
    /// also stops at the viewpoint of each that has one.
    std::vector<UnseenArea> unseen;
    /// How many of the unseen areas' viewpoints became stops: one within 0.3 m of a stop the
    /// tour makes anyway is that stop.
    std::size_t unseenStops = 0;
    std::vector<std::vector<mrpt::math::TPoint2D>> legs;  ///< the smoothed path of each leg
    io::Trajectory2D poses;                               ///< scan poses (world frame), stamps in s
    double length = 0;                                    ///< m driven, all laps
};

/// Plans the tour. Throws std::invalid_argument when the map has no place where the robot fits,
/// no room-sized area, a start pose where the robot does not fit, or laps > 1 without
/// returnToStart.
Tour planTour(const ClearanceMap& map, const TourOptions& options);

}  // namespace toposlam::simulation
