#include <toposlam/simulation/PathSmoother.h>
#include <toposlam/simulation/TourOrder.h>
#include <toposlam/simulation/TourPlanner.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace toposlam::simulation {

using mrpt::math::TPoint2D;

void TourOptions::declare(config::OptionsSchema& s) {
    s.real("robot_radius", robotRadius, "m", "robot footprint radius").above(0);
    s.real("safety_margin", safetyMargin, "m", "kept between the robot's outline and any obstacle")
        .atLeast(0);
    s.real("preferred_clearance", preferredClearance, "m",
           "paths keep this much clearance where they can")
        .atLeast(0);
    s.real("clearance_weight", clearanceWeight, "",
           "steps closer to walls cost up to 1 + clearance_weight times their length")
        .atLeast(0);
    s.real("door_width_max", areas.doorWidthMax, "m",
           "openings up to this wide separate free areas")
        .above(0);
    s.real("min_area_m2", areas.minAreaM2, "m^2",
           "smaller areas (after eroding free space by half the door width) are ignored")
        .atLeast(0);
    s.real("smoothing_sigma", smoothingSigma, "m",
           "Gaussian path smoothing along the path, 1 sigma")
        .atLeast(0);
    s.flag("return_to_start", returnToStart, "close the loop (SLAM needs loops to be tested)");
    s.group("", motion);
}

namespace {
constexpr double kPathSpacing = 0.05;  // m between the points of a smoothed leg

std::string metres(double v) {
    std::ostringstream o;
    o << v << " m";
    return o.str();
}

/// The order in which the tour visits `places` (indices; the first is the start), and the
/// tour's visitOrder / unreachable areas. Areas the start cannot reach are left out.
std::vector<std::size_t> orderPlaces(GridPathPlanner& planner, const ClearanceMap& map,
                                     const std::vector<TPoint2D>& places,
                                     const std::vector<long>& areaOfPlace, bool returnToStart,
                                     Tour& tour) {
    // Path costs between all places; drop areas that cannot be reached from the start.
    std::vector<std::vector<double>> cost(places.size(), std::vector<double>(places.size()));
    for (std::size_t i = 0; i < places.size(); ++i) {
        const std::vector<float>& costs = planner.costsFrom(places[i]);
        const GridGeometry& g = map.geometry();
        for (std::size_t j = 0; j < places.size(); ++j) {
            cost[i][j] = costs[g.index(g.cellX(places[j].x), g.cellY(places[j].y))];
        }
    }
    std::vector<std::size_t> reachable;
    for (std::size_t j = 0; j < places.size(); ++j) {
        if (std::isfinite(cost[0][j])) {
            reachable.push_back(j);
        } else {
            tour.unreachable.push_back(static_cast<std::size_t>(areaOfPlace[j]));
        }
    }
    std::vector<std::vector<double>> reachableCost(reachable.size(),
                                                   std::vector<double>(reachable.size()));
    for (std::size_t i = 0; i < reachable.size(); ++i) {
        for (std::size_t j = 0; j < reachable.size(); ++j) {
            reachableCost[i][j] = cost[reachable[i]][reachable[j]];
        }
    }
    std::vector<std::size_t> order;
    for (std::size_t k : orderVisits(reachableCost, returnToStart)) {
        order.push_back(reachable[k]);
    }
    if (returnToStart && order.size() > 1)
        order.push_back(order.front());
    for (std::size_t p : order) {
        if (areaOfPlace[p] >= 0 &&
            (tour.visitOrder.empty() ||
             tour.visitOrder.back() != static_cast<std::size_t>(areaOfPlace[p]))) {
            tour.visitOrder.push_back(static_cast<std::size_t>(areaOfPlace[p]));
        }
    }
    if (returnToStart && tour.visitOrder.size() > 1 &&
        tour.visitOrder.back() == tour.visitOrder.front()) {
        tour.visitOrder.pop_back();
    }

    return order;
}
}  // namespace

Tour planTour(const ClearanceMap& map, const TourOptions& options) {
    GridPathPlanner planner(map, options.pathCost());
    const double needed = options.pathCost().minClearance;
    bool anyTraversable = false;
    for (float c : map.clearances())
        anyTraversable = anyTraversable || c >= needed;
    if (!anyTraversable) {
        throw std::invalid_argument(
            map.freeCellCount() == 0
                ? "the map has no free cell"
                : "no free place in the map is wide enough for the robot (clearance " +
                      metres(needed) + " = robot radius + safety margin)");
    }

    Tour tour;
    tour.areas = findRoomSizedAreas(map, options.areas);
    if (tour.areas.empty()) {
        throw std::invalid_argument(
            "no room-sized free area in the map (no free place farther "
            "than half the door width, " +
            metres(options.areas.doorWidthMax / 2) + ", from obstacles)");
    }

    // Places: the start, then every area (the default start is the largest area itself).
    std::vector<TPoint2D> places;
    std::vector<long> areaOfPlace;
    if (options.start) {
        const TPoint2D s(options.start->x, options.start->y);
        if (!planner.traversable(s)) {
            throw std::invalid_argument("the start position (" + std::to_string(s.x) + ", " +
                                        std::to_string(s.y) +
                                        ") is not free or too close to an obstacle");
        }
        places.push_back(s);
        areaOfPlace.push_back(-1);
    }
    for (std::size_t a = 0; a < tour.areas.size(); ++a) {
        places.push_back(tour.areas[a].centre);
        areaOfPlace.push_back(static_cast<long>(a));
    }

    const std::vector<std::size_t> order =
        orderPlaces(planner, map, places, areaOfPlace, options.returnToStart, tour);
    for (std::size_t k = 1; k < order.size(); ++k) {
        const auto path = planner.plan(places[order[k - 1]], places[order[k]]);
        tour.legs.push_back(smoothPath(path, planner, options.smoothingSigma, kPathSpacing));
        for (std::size_t i = 1; i < tour.legs.back().size(); ++i) {
            const TPoint2D &a = tour.legs.back()[i - 1], &b = tour.legs.back()[i];
            tour.length += std::hypot(b.x - a.x, b.y - a.y);
        }
    }
    if (tour.legs.empty())
        tour.legs.push_back({places[order.front()]});

    double initialYaw = 0;
    if (options.start) {
        initialYaw = options.start->phi;
    } else if (tour.legs.front().size() > 1) {
        const TPoint2D &a = tour.legs.front()[0], &b = tour.legs.front()[1];
        initialYaw = std::atan2(b.y - a.y, b.x - a.x);
    }
    tour.poses = driveLegs(tour.legs, initialYaw, options.motion);
    return tour;
}

}  // namespace toposlam::simulation
