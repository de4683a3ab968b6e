#include <toposlam/simulation/MovingObstacles.h>
#include <toposlam/simulation/PathSmoother.h>

#include <cmath>

namespace toposlam::simulation {

using mrpt::math::TPoint2D;

void PeopleOptions::declare(config::OptionsSchema& s) {
    s.integer("count", count, "",
              "people walking between random places (discs); 0 = a static world")
        .within(0, 1000);
    s.real("radius", radius, "m", "a person's disc (shoulder half-width)").above(0);
    s.real("min_speed", minSpeed, "m/s", "each walk picks a speed in [min_speed, max_speed]")
        .above(0);
    s.real("max_speed", maxSpeed, "m/s", "fastest walk").above(0);
    s.require([this] { return minSpeed <= maxSpeed; }, "min_speed", "must not exceed max_speed");
    s.real("max_pause", maxPause, "s", "pause at each destination, uniform in [0, max_pause]")
        .atLeast(0);
    s.real("max_trip_length", maxTripLength, "m", "destinations at most this far (straight line)")
        .above(0);
    s.real("robot_keep_out", robotKeepOut, "m", "people keep this far from the robot's centre")
        .atLeast(0);
}

namespace {
// A person's centre keeps one cell more than its radius from obstacle cells: positions between
// two path points then still keep the radius (clearance is 1-Lipschitz, path points are at most
// one cell diagonal apart).
PathCostOptions personCost(const ClearanceMap& map, const PeopleOptions& o) {
    return {o.radius + map.geometry().resolution, o.radius + 0.5, 2.0};
}
constexpr double kGiveUpAfter = 2.0;  // s waiting for the robot before choosing another goal
double dist(const TPoint2D& a, const TPoint2D& b) {
    return std::hypot(a.x - b.x, a.y - b.y);
}
}  // namespace

MovingObstacles::MovingObstacles(const ClearanceMap& map, const PeopleOptions& options,
                                 const TPoint2D& robotStart, unsigned seed)
    : map_(map), options_(options), planner_(map, personCost(map, options)), rng_(seed) {
    const GridGeometry& g = map.geometry();
    for (int cy = 0; cy < g.sizeY; ++cy) {
        for (int cx = 0; cx < g.sizeX; ++cx) {
            if (planner_.traversable(cx, cy))
                freeCells_.push_back(g.index(cx, cy));
        }
    }
    if (freeCells_.empty())
        return;  // nowhere a person fits: nobody walks
    walkers_.resize(options.count);
    discs_.resize(options.count);
    for (std::size_t i = 0; i < options.count; ++i) {
        TPoint2D p = randomFreePlace();
        for (int tries = 0; tries < 100 && dist(p, robotStart) < 1.0; ++tries) {
            p = randomFreePlace();
        }
        discs_[i] = Disc{p, options.radius};
        walkers_[i].pause = std::uniform_real_distribution<double>(0, options.maxPause)(rng_);
    }
}

TPoint2D MovingObstacles::randomFreePlace() {
    std::uniform_int_distribution<std::size_t> pick(0, freeCells_.size() - 1);
    return map_.geometry().centre(freeCells_[pick(rng_)]);
}

void MovingObstacles::startWalk(std::size_t i) {
    Walker& w = walkers_[i];
    const TPoint2D from = discs_[i].centre;
    w.path.clear();
    w.next = 0;
    for (int tries = 0; tries < 20 && w.path.empty(); ++tries) {
        const TPoint2D to = randomFreePlace();
        if (dist(from, to) > options_.maxTripLength || dist(from, to) < 1.0)
            continue;
        w.path = resamplePolyline(planner_.plan(from, to), map_.geometry().resolution);
    }
    w.speed = std::uniform_real_distribution<double>(options_.minSpeed, options_.maxSpeed)(rng_);
    w.pause = std::uniform_real_distribution<double>(0, options_.maxPause)(rng_);
}

bool MovingObstacles::stepAside(std::size_t i, double dt, const TPoint2D& robot) {
    TPoint2D& p = discs_[i].centre;
    const double d = dist(p, robot);
    if (d >= options_.robotKeepOut)
        return false;
    // The robot came too close: walk straight away from it (or sideways if a wall is behind),
    // then choose a new destination.
    const double step = std::min(walkers_[i].speed * dt, options_.robotKeepOut - d);
    const double away = d > 1e-9 ? std::atan2(p.y - robot.y, p.x - robot.x) : 0.0;
    for (double turn : {0.0, M_PI / 4, -M_PI / 4, M_PI / 2, -M_PI / 2}) {
        const TPoint2D q(p.x + step * std::cos(away + turn), p.y + step * std::sin(away + turn));
        if (planner_.traversable(q) && planner_.traversable({(p.x + q.x) / 2, (p.y + q.y) / 2})) {
            p = q;
            break;
        }
    }
    walkers_[i].path.clear();
    walkers_[i].pause = 0;
    return true;
}

void MovingObstacles::advance(double dt, const TPoint2D& robot) {
    for (std::size_t i = 0; i < walkers_.size(); ++i) {
        Walker& w = walkers_[i];
        TPoint2D& p = discs_[i].centre;
        double left = dt;
        if (stepAside(i, dt, robot))
            continue;
        while (left > 1e-9) {
            if (w.next >= w.path.size()) {  // at a destination: wait, then pick the next one
                if (w.pause > left) {
                    w.pause -= left;
                    break;
                }
                left -= w.pause;
                startWalk(i);
                if (w.path.empty())
                    break;  // nowhere to go from here: stay
                w.next = 1;
                continue;
            }
            const TPoint2D target = w.path[w.next];
            const double d = dist(p, target);
            const double step = std::min(d, w.speed * left);
            const TPoint2D q = d > 1e-12 ? TPoint2D{p.x + (target.x - p.x) * step / d,
                                                    p.y + (target.y - p.y) * step / d}
                                         : target;
            // Give way: do not step closer to the robot once within its keep-out distance;
            // after waiting a while, go somewhere else.
            if (dist(q, robot) < options_.robotKeepOut && dist(q, robot) < dist(p, robot)) {
                w.blocked += left;
                if (w.blocked > kGiveUpAfter) {
                    w.path.clear();
                    w.pause = 0;
                }
                break;
            }
            w.blocked = 0;
            p = q;
            left -= step / w.speed;
            if (step >= d)
                ++w.next;
        }
    }
}

}  // namespace toposlam::simulation
