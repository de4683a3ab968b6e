#include <toposlam/matchingbench/SimulatedPairs.h>
#include <toposlam/simulation/LaserModel.h>
#include <toposlam/simulation/PolygonWorld.h>

#include <cmath>
#include <random>

namespace toposlam::matchingbench {

namespace {
using mrpt::math::TPoint2D;
using Polygon = std::vector<TPoint2D>;

bool inside(const Polygon& poly, const TPoint2D& p) {
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
            p.x < (poly[j].x - poly[i].x) * (p.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
            in = !in;
    }
    return in;
}

struct Room {
    Polygon hall;                    // outer walls
    std::vector<Polygon> furniture;  // solid polygons
    std::size_t people = 0;
};

Room emptyRoom() {
    Room r;
    // L-shaped hall 14 m x 9 m with a door niche, a window bay and a square pillar.
    r.hall = {{0, 0},     {9, 0},   {9, -0.4}, {10.2, -0.4}, {10.2, 0},  {14, 0},  {14, 4.5},
              {8.5, 4.5}, {8.5, 9}, {3, 9},    {3, 9.6},     {1.5, 9.6}, {1.5, 9}, {0, 9}};
    r.furniture = {{{5.0, 2.0}, {5.5, 2.0}, {5.5, 2.5}, {5.0, 2.5}}};  // pillar
    return r;
}

Room clutteredRoom() {
    Room r = emptyRoom();
    const std::vector<Polygon> items = {
        {{1.0, 1.0}, {2.6, 1.0}, {2.6, 1.8}, {1.0, 1.8}},      // table
        {{0.0, 4.0}, {0.5, 4.0}, {0.5, 6.5}, {0.0, 6.5}},      // cabinets along a wall
        {{11.0, 1.2}, {12.3, 1.5}, {12.1, 2.3}, {10.8, 2.0}},  // skewed desk
        {{6.5, 6.0}, {7.3, 6.0}, {7.3, 6.6}, {6.5, 6.6}},      // box
        {{3.2, 6.8}, {4.4, 6.8}, {4.4, 7.3}, {3.2, 7.3}},      // shelf
        {{12.8, 3.6}, {14.0, 3.6}, {14.0, 4.5}, {12.8, 4.5}},  // corner cupboard
        {{7.6, 2.8}, {8.0, 2.8}, {8.0, 3.2}, {7.6, 3.2}},      // crate
        {{2.0, 3.5}, {2.7, 3.2}, {3.0, 3.9}, {2.3, 4.2}},      // rotated box
    };
    r.furniture.insert(r.furniture.end(), items.begin(), items.end());
    r.people = 6;
    return r;
}

bool freeAt(const Room& room, const simulation::PolygonWorld& world, const TPoint2D& p,
            double clearance) {
    if (!inside(room.hall, p))
        return false;
    for (const Polygon& f : room.furniture)
        if (inside(f, p))
            return false;
    for (const simulation::Disc& d : world.discs())
        if (std::hypot(p.x - d.centre.x, p.y - d.centre.y) < d.radius + clearance)
            return false;
    for (int k = 0; k < 16; ++k)
        if (world.castRay(p, k * M_PI / 8, clearance) < clearance)
            return false;
    return true;
}

struct Generator {
    const Room& room;
    std::mt19937& rng;
    simulation::PolygonWorld world;

    explicit Generator(const Room& r, std::mt19937& g) : room(r), rng(g) {
        world.addPolygon(room.hall);
        for (const Polygon& f : room.furniture)
            world.addPolygon(f);
    }
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
    TPoint2D freePoint() {
        for (;;) {
            // y before x, sequenced: the order GCC gave the two when both were arguments.
            const double y = uniform(0, 9.6), x = uniform(0, 14);
            const TPoint2D p(x, y);
            if (freeAt(room, world, p, 0.4))
                return p;
        }
    }
};
}  // namespace

ScanPairs makeSimulatedPairs(const SimulatedPairsOptions& options) {
    std::mt19937 rng(options.seed);
    simulation::LaserModel laser;
    laser.beams = 360;
    laser.aperture = 2 * M_PI * 359.0 / 360.0;
    laser.maxRange = 20.0;
    laser.rangeNoiseStd = options.rangeNoiseStd;
    laser.sensorLabel = "LASER_SIM";

    const double offsets[] = {0.05, 0.15, 0.5, 1.0};
    const double rotations[] = {0.0, 30.0, 90.0, 180.0};
    ScanPairs pairs;
    for (const auto& [name, room] :
         {std::pair<const char*, Room>{"sim-empty", emptyRoom()},
          std::pair<const char*, Room>{"sim-cluttered", clutteredRoom()}}) {
        Generator gen(room, rng);
        for (const double offset : offsets) {
            for (const double rotationDeg : rotations) {
                for (std::size_t k = 0; k < options.pairsPerCase; ++k) {
                    // People where they are at the first scan (within free space).
                    gen.world.discs().clear();
                    for (std::size_t p = 0; p < room.people; ++p)
                        gen.world.addDisc({gen.freePoint(), 0.25});
                    // Reference pose, motion, current pose (both in free space).
                    mrpt::poses::CPose2D ref, cur, motion;
                    for (;;) {
                        const TPoint2D a = gen.freePoint();
                        ref = mrpt::poses::CPose2D(a.x, a.y, gen.uniform(-M_PI, M_PI));
                        const double dir = gen.uniform(-M_PI, M_PI);
                        const double sign = gen.uniform(0, 1) < 0.5 ? -1.0 : 1.0;
                        motion =
                            mrpt::poses::CPose2D(offset * std::cos(dir), offset * std::sin(dir),
                                                 sign * rotationDeg * M_PI / 180.0);
                        cur = ref + motion;
                        if (freeAt(room, gen.world, TPoint2D(cur.x(), cur.y()), 0.4))
                            break;
                    }
                    ScanPair pair;
                    pair.set = name;
                    pair.truth = motion;
                    pair.offset = offset;
                    pair.rotation = rotationDeg * M_PI / 180.0;
                    pair.reference = mrpt::obs::CObservation2DRangeScan::Create(
                        simulation::simulateScan(gen.world, laser, ref, rng));
                    // The people walk: each moves up to 0.5 m (staying in free space).
                    for (simulation::Disc& d : gen.world.discs()) {
                        for (int attempt = 0; attempt < 20; ++attempt) {
                            const double a = gen.uniform(-M_PI, M_PI), r = gen.uniform(0, 0.5);
                            const TPoint2D moved(d.centre.x + r * std::cos(a),
                                                 d.centre.y + r * std::sin(a));
                            if (inside(room.hall, moved) &&
                                std::hypot(moved.x - cur.x(), moved.y - cur.y()) > 0.7 &&
                                std::hypot(moved.x - ref.x(), moved.y - ref.y()) > 0.7) {
                                d.centre = moved;
                                break;
                            }
                        }
                    }
                    pair.current = mrpt::obs::CObservation2DRangeScan::Create(
                        simulation::simulateScan(gen.world, laser, cur, rng));
                    const double e = gen.uniform(-M_PI, M_PI);
                    pair.odometry =
                        motion + mrpt::poses::CPose2D(options.guessTranslationError * std::cos(e),
                                                      options.guessTranslationError * std::sin(e),
                                                      (gen.uniform(0, 1) < 0.5 ? -1 : 1) *
                                                          options.guessRotationError);
                    pairs.push_back(std::move(pair));
                }
            }
        }
    }
    return pairs;
}

}  // namespace toposlam::matchingbench
