#include <toposlam/simulation/PathSmoother.h>
#include <toposlam/simulation/TourCoverage.h>
#include <toposlam/simulation/TourOrder.h>
#include <toposlam/simulation/TourPlanner.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

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
    s.integer("laps", laps, "",
              "drive the closed tour this many times (a long log that keeps coming back, as a "
              "patrolling robot records it; needs return_to_start)")
        .within(1, 1000);
    s.flag("look_into_unseen", coverage.lookIntoUnseen,
           "also stop where the robot sees the free areas the room-sized tour leaves unseen "
           "(closets, rooms behind a vestibule, space behind furniture)");
    s.real("view_range", coverage.viewRange, "m",
           "a free cell counts as seen from a path point this close in line of sight")
        .above(0);
    s.real("min_unseen_area_m2", coverage.minUnseenAreaM2, "m^2",
           "unseen areas smaller than this are left unseen")
        .atLeast(0);
    s.group("", motion);
}

namespace {
constexpr double kPathSpacing = 0.05;  // m between the points of a smoothed leg
constexpr std::size_t kViewEvery = 5;  // path points between two sight checks (0.25 m)
constexpr double kSameStop = 0.3;      // m: viewpoints this close to a stop are that stop

std::string metres(double v) {
    std::ostringstream o;
    o << v << " m";
    return o.str();
}

/// The order in which the tour visits `places` (indices; the first is the start), and the
/// tour's visitOrder / unreachable areas. Areas the start cannot reach are left out.
std::vector<std::size_t> orderPlaces(GridPathPlanner& planner, const std::vector<TPoint2D>& places,
                                     const std::vector<long>& areaOfPlace, bool returnToStart,
                                     Tour& tour) {
    // Path costs between all places; drop areas that cannot be reached from the start.
    std::vector<std::vector<double>> cost(places.size(), std::vector<double>(places.size()));
    for (std::size_t i = 0; i < places.size(); ++i) {
        const std::vector<float> costs = planner.costsTo(places[i], places);
        std::copy(costs.begin(), costs.end(), cost[i].begin());
    }
    std::vector<std::size_t> reachable;
    for (std::size_t j = 0; j < places.size(); ++j) {
        if (std::isfinite(cost[0][j])) {
            reachable.push_back(j);
        } else if (areaOfPlace[j] >= 0) {
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

/// Plans, smooths and measures the legs between consecutive places of `order` into `tour`.
void planLegs(GridPathPlanner& planner, const std::vector<TPoint2D>& places,
              const std::vector<std::size_t>& order, double smoothingSigma, Tour& tour) {
    tour.legs.clear();
    tour.length = 0;
    for (std::size_t k = 1; k < order.size(); ++k) {
        const auto path = planner.plan(places[order[k - 1]], places[order[k]]);
        tour.legs.push_back(smoothPath(path, planner, smoothingSigma, kPathSpacing));
        for (std::size_t i = 1; i < tour.legs.back().size(); ++i) {
            const TPoint2D &a = tour.legs.back()[i - 1], &b = tour.legs.back()[i];
            tour.length += std::hypot(b.x - a.x, b.y - a.y);
        }
    }
    if (tour.legs.empty())
        tour.legs.push_back({places[order.front()]});
}

/// The default start among the `toured` areas (indices, largest first): the largest area of
/// the group of areas reachable from one another that holds the most areas (then the most
/// area). A free courtyard, or the free background around a drawn building, is one large area
/// from where no room is reached.
std::size_t defaultStartArea(GridPathPlanner& planner, const std::vector<RoomSizedArea>& areas,
                             const std::vector<std::size_t>& toured) {
    std::vector<TPoint2D> centres;
    for (std::size_t a : toured)
        centres.push_back(areas[a].centre);
    std::vector<bool> grouped(areas.size(), false);
    std::size_t best = toured.front();
    std::pair<std::size_t, double> bestSize{0, 0.0};  // areas, m^2
    for (std::size_t first : toured) {
        if (grouped[first])
            continue;
        const std::vector<float> costs = planner.costsTo(areas[first].centre, centres);
        std::pair<std::size_t, double> size{0, 0.0};
        for (std::size_t k = 0; k < toured.size(); ++k) {
            const std::size_t a = toured[k];
            if (!grouped[a] && std::isfinite(costs[k])) {
                grouped[a] = true;
                ++size.first;
                size.second += areas[a].erodedAreaM2;
            }
        }
        if (size > bestSize) {
            bestSize = size;
            best = first;
        }
    }
    return best;
}

/// Every kViewEvery-th point of the legs, and each leg's last: where the laser looks from.
std::vector<TPoint2D> pointsAlong(const std::vector<std::vector<TPoint2D>>& legs) {
    std::vector<TPoint2D> points;
    for (const auto& leg : legs) {
        for (std::size_t i = 0; i < leg.size(); i += kViewEvery)
            points.push_back(leg[i]);
        if (!leg.empty())
            points.push_back(leg.back());
    }
    return points;
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

    // Places: the start, then every area toured (the default start is an area itself).
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
    const bool anyEnclosed = std::any_of(tour.areas.begin(), tour.areas.end(),
                                         [](const RoomSizedArea& a) { return !a.openToMapEdge; });
    std::vector<std::size_t> toured;
    for (std::size_t a = 0; a < tour.areas.size(); ++a)
        (anyEnclosed && tour.areas[a].openToMapEdge ? tour.outside : toured).push_back(a);
    if (!options.start) {
        // The start first: the areas the robot can reach from it are the ones it tours.
        const std::size_t start = defaultStartArea(planner, tour.areas, toured);
        const auto first = std::find(toured.begin(), toured.end(), start);
        std::rotate(toured.begin(), first, first + 1);
    }
    for (std::size_t a : toured) {
        places.push_back(tour.areas[a].centre);
        areaOfPlace.push_back(static_cast<long>(a));
    }

    std::vector<std::size_t> order =
        orderPlaces(planner, places, areaOfPlace, options.returnToStart, tour);
    planLegs(planner, places, order, options.smoothingSigma, tour);
    if (options.coverage.lookIntoUnseen) {
        // Where the robot can get to from the start, and what the tour so far has in view.
        const std::vector<float>& costs = planner.costsFrom(places[order.front()]);
        std::vector<std::uint8_t> reachable(costs.size());
        for (std::size_t i = 0; i < costs.size(); ++i)
            reachable[i] = std::isfinite(costs[i]) ? 1 : 0;
        tour.unseen = findUnseenAreas(
            map, cellsInView(map, pointsAlong(tour.legs), options.coverage.viewRange), reachable,
            options.coverage, !tour.outside.empty());
        const std::size_t before = places.size();
        for (const UnseenArea& u : tour.unseen) {
            for (const TPoint2D& v : u.viewpoints) {
                // A stop next to one the tour makes anyway adds nothing but a twitch.
                const bool nearStop =
                    std::any_of(places.begin(), places.end(), [&](const TPoint2D& p) {
                        return std::hypot(p.x - v.x, p.y - v.y) < kSameStop;
                    });
                if (!nearStop) {
                    places.push_back(v);
                    areaOfPlace.push_back(-1);
                }
            }
        }
        tour.unseenStops = places.size() - before;
        if (places.size() > before) {  // the same tour, with the viewpoints among its stops
            tour.visitOrder.clear();
            tour.unreachable.clear();
            order = orderPlaces(planner, places, areaOfPlace, options.returnToStart, tour);
            planLegs(planner, places, order, options.smoothingSigma, tour);
        }
    }

    if (options.laps > 1) {
        if (!options.returnToStart)
            throw std::invalid_argument("laps > 1 needs return_to_start: the tour must be closed");
        const std::vector<std::vector<TPoint2D>> lap = tour.legs;
        for (int k = 1; k < options.laps; ++k)
            tour.legs.insert(tour.legs.end(), lap.begin(), lap.end());
        tour.length *= options.laps;
    }

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
