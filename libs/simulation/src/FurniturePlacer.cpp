#include <toposlam/simulation/FurniturePlacer.h>

#include <algorithm>
#include <cmath>

namespace toposlam::simulation {

using mrpt::math::TPoint2D;

namespace {

bool overlaps(const Box& a, const Box& b, double margin) {
    return a.xMin < b.xMax + margin && b.xMin < a.xMax + margin && a.yMin < b.yMax + margin &&
           b.yMin < a.yMax + margin;
}

double lengthOf(const Box& b, int side) {
    return side < 2 ? b.xMax - b.xMin : b.yMax - b.yMin;
}

// The wall sides of a room, longest first (people put the big pieces along the long walls).
std::vector<int> sidesByLength(const Box& floor) {
    const bool wide = floor.xMax - floor.xMin >= floor.yMax - floor.yMin;
    return wide ? std::vector<int>{0, 1, 2, 3} : std::vector<int>{2, 3, 0, 1};
}

}  // namespace

FurniturePlacer::FurniturePlacer(FloorPlan& plan, std::mt19937& rng)
    : plan_(plan), rng_(rng), walls_(plan.wallPieces()) {
    for (const FloorDoor& d : plan.doors()) {
        const bool horizontal = std::abs(d.jambA.y - d.jambB.y) < 1e-9;
        const double x0 = std::min(d.jambA.x, d.jambB.x), x1 = std::max(d.jambA.x, d.jambB.x);
        const double y0 = std::min(d.jambA.y, d.jambB.y), y1 = std::max(d.jambA.y, d.jambB.y);
        doorZones_.push_back(horizontal ? Box{x0 - 0.15, y0 - 1.1, x1 + 0.15, y1 + 1.1}
                                        : Box{x0 - 1.1, y0 - 0.15, x1 + 1.1, y1 + 0.15});
        doorways_.push_back(horizontal ? Box{x0, y0 - 0.4, x1, y1 + 0.4}
                                       : Box{x0 - 0.4, y0, x1 + 0.4, y1});
    }
}

// Every random draw is sequenced: its own statement, or the only draw among a call's arguments.
// The order in which a call's arguments are evaluated is up to the compiler, so two draws in
// one call made the plans differ between GCC and clang. Where a call held several, they are
// now drawn in the order GCC evaluated them, last argument first, so that the plans (and every
// benchmark figure measured on them) stay as they were.
double FurniturePlacer::uniform(double a, double b) {
    return a >= b ? a : std::uniform_real_distribution<>(a, b)(rng_);
}

bool FurniturePlacer::chance(double p) {
    return uniform(0, 1) < p;
}

bool FurniturePlacer::fits(const FloorRoom& room, const Box& f) const {
    const Box& r = room.floor;
    if (f.xMin < r.xMin - 1e-9 || f.yMin < r.yMin - 1e-9 || f.xMax > r.xMax + 1e-9 ||
        f.yMax > r.yMax + 1e-9) {
        return false;
    }
    auto hits = [&](const std::vector<Box>& boxes, double margin) {
        return std::any_of(boxes.begin(), boxes.end(),
                           [&](const Box& b) { return overlaps(f, b, margin); });
    };
    // Walls may be touched (furniture stands against them) but not entered (partition stubs
    // inside the floor); other pieces keep 5 cm (chairs reserve no space).
    return !hits(walls_, -1e-6) && !hits(doorZones_, 0.0) && !hits(placed_, 0.05);
}

bool FurniturePlacer::reserve(const FloorRoom& room, const Box& f) {
    if (!fits(room, f))
        return false;
    placed_.push_back(f);
    return true;
}

bool FurniturePlacer::againstWall(const FloorRoom& room, int side, double length, double depth,
                                  double gap, Box& out) {
    const Box& r = room.floor;
    if (length > lengthOf(r, side) - 0.1)
        length = lengthOf(r, side) - 0.1;
    if (length < 0.3)
        return false;
    for (int attempt = 0; attempt < 12; ++attempt) {
        const double along = uniform(0, lengthOf(r, side) - length);
        switch (side) {
            case 0:
                out = {r.xMin + along, r.yMin + gap, r.xMin + along + length, r.yMin + gap + depth};
                break;
            case 1:
                out = {r.xMin + along, r.yMax - gap - depth, r.xMin + along + length, r.yMax - gap};
                break;
            case 2:
                out = {r.xMin + gap, r.yMin + along, r.xMin + gap + depth, r.yMin + along + length};
                break;
            default:
                out = {r.xMax - gap - depth, r.yMin + along, r.xMax - gap, r.yMin + along + length};
                break;
        }
        if (reserve(room, out))
            return true;
    }
    return false;
}

bool FurniturePlacer::solidAgainstWall(const FloorRoom& room, int side, double length, double depth,
                                       double gap) {
    Box b;
    if (!againstWall(room, side, length, depth, gap, b))
        return false;
    solid(b);
    ++pieces_;
    return true;
}

void FurniturePlacer::solid(const Box& b) {
    plan_.addFurniture(b);
}

void FurniturePlacer::legs(const Box& b) {
    constexpr double leg = 0.05, inset = 0.03;
    std::vector<double> xs{b.xMin + inset, b.xMax - inset - leg};
    std::vector<double> ys{b.yMin + inset, b.yMax - inset - leg};
    if (b.xMax - b.xMin > 2.0)
        xs.push_back(0.5 * (b.xMin + b.xMax - leg));
    if (b.yMax - b.yMin > 2.0)
        ys.push_back(0.5 * (b.yMin + b.yMax - leg));
    for (double x : xs) {
        for (double y : ys)
            plan_.addFurniture(Box{x, y, x + leg, y + leg});
    }
}

void FurniturePlacer::desk(const Box& b) {
    const double r = uniform(0, 1);
    const bool alongX = b.xMax - b.xMin >= b.yMax - b.yMin;
    if (r < 0.5) {
        legs(b);
    } else if (r < 0.8) {  // a drawer pedestal at one end, legs at the other
        const double p = 0.4;
        const bool first = chance(0.5);
        Box pedestal = b, rest = b;
        if (alongX) {
            pedestal = first ? Box{b.xMin, b.yMin, b.xMin + p, b.yMax}
                             : Box{b.xMax - p, b.yMin, b.xMax, b.yMax};
            rest = first ? Box{b.xMin + p, b.yMin, b.xMax, b.yMax}
                         : Box{b.xMin, b.yMin, b.xMax - p, b.yMax};
        } else {
            pedestal = first ? Box{b.xMin, b.yMin, b.xMax, b.yMin + p}
                             : Box{b.xMin, b.yMax - p, b.xMax, b.yMax};
            rest = first ? Box{b.xMin, b.yMin + p, b.xMax, b.yMax}
                         : Box{b.xMin, b.yMin, b.xMax, b.yMax - p};
        }
        solid(pedestal);
        legs(rest);
    } else {  // two side panels
        constexpr double t = 0.03;
        if (alongX) {
            solid({b.xMin, b.yMin, b.xMin + t, b.yMax});
            solid({b.xMax - t, b.yMin, b.xMax, b.yMax});
        } else {
            solid({b.xMin, b.yMin, b.xMax, b.yMin + t});
            solid({b.xMin, b.yMax - t, b.xMax, b.yMax});
        }
    }
    ++pieces_;
}

void FurniturePlacer::chair(const TPoint2D& p) {
    // Chairs reserve no space, but nobody leaves one in a wall or a doorway.
    const Box around{p.x - 0.1, p.y - 0.1, p.x + 0.1, p.y + 0.1};
    auto hits = [&](const std::vector<Box>& boxes) {
        return std::any_of(boxes.begin(), boxes.end(),
                           [&](const Box& b) { return overlaps(around, b, 0.0); });
    };
    if (plan_.roomAt(p) == 0 || hits(walls_) || hits(doorways_))
        return;
    plan_.addFurniture(Disc{p, uniform(0.03, 0.05)});
    ++pieces_;
}

void FurniturePlacer::disc(const TPoint2D& p, double radius) {
    plan_.addFurniture(Disc{p, radius});
    ++pieces_;
}

void FurniturePlacer::chairInFront(const Box& d, int side) {
    const double away = uniform(0.3, 0.6);
    const double cx = 0.5 * (d.xMin + d.xMax) + uniform(-0.3, 0.3);
    const double cy = 0.5 * (d.yMin + d.yMax) + uniform(-0.3, 0.3);
    switch (side) {
        case 0:
            chair({cx, d.yMax + away});
            break;
        case 1:
            chair({cx, d.yMin - away});
            break;
        case 2:
            chair({d.xMax + away, cy});
            break;
        default:
            chair({d.xMin - away, cy});
            break;
    }
}

void FurniturePlacer::cornerPlant(const FloorRoom& room) {
    const double r = uniform(0.15, 0.3);
    const Box& f = room.floor;
    const double x = chance(0.5) ? f.xMin + r + 0.05 : f.xMax - r - 0.05;
    const double y = chance(0.5) ? f.yMin + r + 0.05 : f.yMax - r - 0.05;
    if (reserve(room, {x - r, y - r, x + r, y + r}))
        disc({x, y}, r);
}

void FurniturePlacer::shelves(const FloorRoom& room, int count) {
    for (int k = 0; k < count; ++k) {
        const int side = std::uniform_int_distribution<>(0, 3)(rng_);
        const double gap = chance(0.7) ? 0.0 : uniform(0.01, 0.05);
        const double depth = uniform(0.35, 0.45);
        solidAgainstWall(room, side, uniform(0.8, 2.0), depth, gap);
    }
}

void FurniturePlacer::furnish(const FloorRoom& room) {
    if (room.kind == "office")
        office(room);
    else if (room.kind == "meeting")
        meeting(room);
    else if (room.kind == "kitchen")
        kitchen(room);
    else if (room.kind == "storage")
        storage(room);
    else if (room.kind == "lab")
        lab(room);
    else if (room.kind == "open plan")
        openPlan(room);
    else if (room.kind == "corridor")
        corridor(room);
    else if (room.kind == "living")
        living(room);
    else if (room.kind == "bedroom")
        bedroom(room);
    else if (room.kind == "bathroom")
        bathroom(room);
    else if (room.kind == "hall")
        hall(room);
    else
        shelves(room, 2);
}

void FurniturePlacer::office(const FloorRoom& room) {
    const int desks = 1 + (chance(0.5) ? 1 : 0) + (room.floor.area() > 16 ? 1 : 0);
    const std::vector<int> sides = sidesByLength(room.floor);
    for (int k = 0; k < desks; ++k) {
        const int side = sides[static_cast<std::size_t>(k % 2 == 0 ? k / 2 % 2 : 2 + k / 2 % 2)];
        Box d;
        const double gap = chance(0.6) ? 0.0 : uniform(0.02, 0.15);
        const double depth = uniform(0.7, 0.8);
        if (againstWall(room, side, uniform(1.2, 1.8), depth, gap, d)) {
            desk(d);
            chairInFront(d, side);
            if (chance(0.4)) {  // a bin beside the desk
                const double r = uniform(0.12, 0.17);
                const TPoint2D c{d.xMax + r + 0.05, d.yMin + r + 0.05};
                if (reserve(room, {c.x - r, c.y - r, c.x + r, c.y + r}))
                    disc(c, r);
            }
        }
    }
    shelves(room, 1 + (chance(0.5) ? 1 : 0));
    if (chance(0.5))
        cornerPlant(room);
}

void FurniturePlacer::meeting(const FloorRoom& room) {
    const Box& f = room.floor;
    const bool alongX = f.xMax - f.xMin >= f.yMax - f.yMin;
    const double longSide = alongX ? f.xMax - f.xMin : f.yMax - f.yMin;
    const double length = uniform(0.45, 0.65) * longSide, width = uniform(0.9, 1.3);
    const TPoint2D c{0.5 * (f.xMin + f.xMax) + uniform(-0.3, 0.3),
                     0.5 * (f.yMin + f.yMax) + uniform(-0.3, 0.3)};
    const double hx = alongX ? length / 2 : width / 2, hy = alongX ? width / 2 : length / 2;
    const Box table{c.x - hx, c.y - hy, c.x + hx, c.y + hy};
    if (reserve(room, table)) {
        legs(table);
        ++pieces_;
        const double spacing = uniform(0.6, 0.8), off = uniform(0.15, 0.35);
        for (double t = spacing / 2; t < length; t += spacing) {
            if (alongX) {
                chair({table.xMin + t, table.yMin - off});
                chair({table.xMin + t, table.yMax + off});
            } else {
                chair({table.xMin - off, table.yMin + t});
                chair({table.xMax + off, table.yMin + t});
            }
        }
    }
    if (chance(0.5)) {  // a sideboard
        const double length = uniform(1.2, 2.4);
        solidAgainstWall(room, sidesByLength(f)[std::uniform_int_distribution<>(0, 3)(rng_)],
                         length, 0.45, 0.0);
    }
    if (chance(0.6))
        cornerPlant(room);
}

void FurniturePlacer::kitchen(const FloorRoom& room) {
    const std::vector<int> sides = sidesByLength(room.floor);
    const int side = sides[std::uniform_int_distribution<>(0, 1)(rng_)];
    solidAgainstWall(room, side, uniform(0.6, 0.9) * lengthOf(room.floor, side), 0.6,
                     0.0);  // the counter
    solidAgainstWall(       // the fridge
        room, sides[static_cast<std::size_t>(2 + std::uniform_int_distribution<>(0, 1)(rng_))],
        0.65, 0.65, 0.02);
    // A small table with chairs somewhere in the middle.
    const Box& f = room.floor;
    for (int attempt = 0; attempt < 10; ++attempt) {
        const double w = uniform(0.7, 1.2), h = 0.8;
        const double x = uniform(f.xMin + 0.7, f.xMax - 0.7 - w),
                     y = uniform(f.yMin + 0.7, f.yMax - 0.7 - h);
        const Box table{x, y, x + w, y + h};
        if (!reserve(room, table))
            continue;
        legs(table);
        ++pieces_;
        chair({x - 0.3, y + h / 2});
        chair({x + w + 0.3, y + h / 2});
        if (chance(0.5))
            chair({x + w / 2, y - 0.3});
        break;
    }
}

void FurniturePlacer::storage(const FloorRoom& room) {
    for (int side = 0; side < 4; ++side) {
        if (chance(0.8)) {
            const double depth = uniform(0.4, 0.6);
            solidAgainstWall(room, side, uniform(0.6, 0.95) * lengthOf(room.floor, side), depth,
                             0.0);
        }
    }
    const Box& f = room.floor;
    const double w = 0.6, h = 0.7;
    const double x = uniform(f.xMin + 1.0, f.xMax - 1.0 - w),
                 y = uniform(f.yMin + 1.0, f.yMax - 1.0 - h);
    if (reserve(room, {x, y, x + w, y + h})) {
        solid({x, y, x + w, y + h});  // copier
        ++pieces_;
    }
}

void FurniturePlacer::lab(const FloorRoom& room) {
    const std::vector<int> sides = sidesByLength(room.floor);
    for (int k = 0; k < 3; ++k) {
        Box b;
        const int side = sides[static_cast<std::size_t>(k)];
        const double depth = uniform(0.75, 0.9);
        if (againstWall(room, side, uniform(0.5, 0.85) * lengthOf(room.floor, side), depth, 0.0,
                        b)) {
            solid(b);
            ++pieces_;
            chairInFront(b, side);
        }
    }
    // Free-standing benches in rows along the long side, aisles of 1-1.6 m.
    const Box& f = room.floor;
    const bool alongX = f.xMax - f.xMin >= f.yMax - f.yMin;
    const double aisle = uniform(1.0, 1.6), depth = 1.5;
    const double across0 = alongX ? f.yMin : f.xMin, across1 = alongX ? f.yMax : f.xMax;
    for (double a = across0 + 0.9 + aisle; a + depth + aisle + 0.9 < across1; a += depth + aisle) {
        const double len = uniform(3.0, 6.0);
        const double s0 = (alongX ? f.xMin : f.yMin) + uniform(1.2, 2.5);
        const Box bench =
            alongX ? Box{s0, a, s0 + len, a + depth} : Box{a, s0, a + depth, s0 + len};
        if (!reserve(room, bench))
            continue;
        chance(0.5) ? solid(bench) : legs(bench);
        ++pieces_;
    }
    if (chance(0.5))
        cornerPlant(room);
}

void FurniturePlacer::openPlan(const FloorRoom& room) {
    // Islands of desks back to back (up to k per side), in a grid with aisles between them; an
    // island that does not fit (a partition, a door) gets fewer desks.
    const Box& f = room.floor;
    const int most = std::uniform_int_distribution<>(2, 4)(rng_);
    const double dw = uniform(1.4, 1.6), dd = 0.8, aisleX = uniform(1.0, 1.8),
                 aisleY = uniform(1.2, 1.8);
    for (double y = f.yMin + uniform(1.0, 1.6); y + 2 * dd + 0.9 < f.yMax; y += 2 * dd + aisleY) {
        double x = f.xMin + uniform(1.0, 1.6);
        while (x + dw + 0.9 < f.xMax) {
            int k = most;
            while (k > 0 && !reserve(room, {x, y, x + k * dw, y + 2 * dd}))
                --k;
            if (k == 0) {
                x += dw;
                continue;
            }
            for (int i = 0; i < k; ++i) {
                for (int row = 0; row < 2; ++row) {
                    const Box d{x + i * dw, y + row * dd, x + (i + 1) * dw, y + (row + 1) * dd};
                    desk(d);
                    if (chance(0.85))
                        chair({0.5 * (d.xMin + d.xMax) + uniform(-0.3, 0.3),
                               row == 0 ? d.yMin - uniform(0.3, 0.6) : d.yMax + uniform(0.3, 0.6)});
                }
            }
            x += k * dw + aisleX;
        }
    }
    shelves(room, 2 + std::uniform_int_distribution<>(0, 2)(rng_));
    if (chance(0.4)) {  // a sofa
        const double length = uniform(1.6, 2.2);
        solidAgainstWall(room, std::uniform_int_distribution<>(0, 3)(rng_), length, 0.85, 0.05);
    }
    for (int p = 0; p < 2; ++p) {
        if (chance(0.6))
            cornerPlant(room);
    }
}

void FurniturePlacer::corridor(const FloorRoom& room) {
    const int n = std::uniform_int_distribution<>(0, 3)(rng_);
    const std::vector<int> sides = sidesByLength(room.floor);
    for (int k = 0; k < n; ++k) {
        const int side =
            sides[static_cast<std::size_t>(std::uniform_int_distribution<>(0, 1)(rng_))];
        Box b;
        const double r = uniform(0, 1);
        if (r < 0.4) {
            const double radius = uniform(0.15, 0.3);
            if (againstWall(room, side, 2 * radius, 2 * radius, 0.05, b))
                disc({0.5 * (b.xMin + b.xMax), 0.5 * (b.yMin + b.yMax)}, radius);
        } else {  // a cabinet, bench or coat rack
            const double depth = uniform(0.35, 0.45);
            solidAgainstWall(room, side, uniform(0.8, 1.2), depth, 0.0);
        }
    }
}

namespace {
/// The wall across the room from `side` (0 south, 1 north, 2 west, 3 east).
int opposite(int side) {
    return side ^ 1;
}
}  // namespace

void FurniturePlacer::beside(const FloorRoom& room, const Box& next, int side, bool high,
                             double size) {
    const Box& r = room.floor;
    constexpr double gap = 0.05;
    Box b;
    if (side < 2) {  // along x
        const double x0 = high ? next.xMax + gap : next.xMin - gap - size;
        b = side == 0 ? Box{x0, r.yMin, x0 + size, r.yMin + size}
                      : Box{x0, r.yMax - size, x0 + size, r.yMax};
    } else {
        const double y0 = high ? next.yMax + gap : next.yMin - gap - size;
        b = side == 2 ? Box{r.xMin, y0, r.xMin + size, y0 + size}
                      : Box{r.xMax - size, y0, r.xMax, y0 + size};
    }
    if (reserve(room, b)) {
        solid(b);
        ++pieces_;
    }
}

void FurniturePlacer::living(const FloorRoom& room) {
    const Box& f = room.floor;
    const std::vector<int> sides = sidesByLength(f);
    const int side = sides[static_cast<std::size_t>(std::uniform_int_distribution<>(0, 1)(rng_))];
    Box sofa;
    const double sofaGap = uniform(0.0, 0.1), sofaDepth = uniform(0.85, 0.95);
    if (againstWall(room, side, uniform(1.8, 2.4), sofaDepth, sofaGap, sofa)) {
        solid(sofa);
        ++pieces_;
        // The coffee table in front of it, on legs.
        const double away = uniform(0.35, 0.5), length = uniform(0.9, 1.2),
                     depth = uniform(0.5, 0.6);
        const double cx = 0.5 * (sofa.xMin + sofa.xMax), cy = 0.5 * (sofa.yMin + sofa.yMax);
        Box table;
        switch (side) {
            case 0:
                table = {cx - length / 2, sofa.yMax + away, cx + length / 2,
                         sofa.yMax + away + depth};
                break;
            case 1:
                table = {cx - length / 2, sofa.yMin - away - depth, cx + length / 2,
                         sofa.yMin - away};
                break;
            case 2:
                table = {sofa.xMax + away, cy - length / 2, sofa.xMax + away + depth,
                         cy + length / 2};
                break;
            default:
                table = {sofa.xMin - away - depth, cy - length / 2, sofa.xMin - away,
                         cy + length / 2};
                break;
        }
        if (reserve(room, table)) {
            legs(table);
            ++pieces_;
        }
        if (chance(0.5)) {
            const double size = uniform(0.75, 0.85);
            beside(room, sofa, side, chance(0.5), size);  // an armchair
        }
        const double tvDepth = uniform(0.4, 0.5);
        solidAgainstWall(room, opposite(side), uniform(1.2, 1.8), tvDepth, 0.0);  // a TV unit
    }
    // A dining table with chairs round it in a large room.
    if (f.area() > 16 && chance(0.6)) {
        for (int attempt = 0; attempt < 10; ++attempt) {
            const double w = uniform(1.2, 1.8), h = uniform(0.8, 0.9);
            const double x = uniform(f.xMin + 0.8, f.xMax - 0.8 - w),
                         y = uniform(f.yMin + 0.8, f.yMax - 0.8 - h);
            const Box table{x, y, x + w, y + h};
            if (!reserve(room, table))
                continue;
            legs(table);
            ++pieces_;
            for (double t = 0.35; t < w; t += 0.6) {
                chair({x + t, y - 0.3});
                chair({x + t, y + h + 0.3});
            }
            break;
        }
    }
    shelves(room, 1 + (chance(0.5) ? 1 : 0));
    if (chance(0.6))
        cornerPlant(room);
}

void FurniturePlacer::bedroom(const FloorRoom& room) {
    const Box& f = room.floor;
    const bool dbl = f.area() >= 10 && chance(0.7);
    const double width = dbl ? uniform(1.4, 1.8) : uniform(0.9, 1.0), length = uniform(2.0, 2.1);
    // The head against a wall, the long walls tried first.
    std::vector<int> sides = sidesByLength(f);
    if (chance(0.5))
        std::swap(sides[0], sides[1]);
    Box bed;
    int side = -1;
    for (int s : sides) {
        if (againstWall(room, s, width, length, 0.0, bed)) {
            side = s;
            break;
        }
    }
    if (side >= 0) {
        solid(bed);  // frame and mattress: solid at 0.3 m
        ++pieces_;
        for (const bool high : {false, true}) {
            if (chance(dbl ? 0.8 : 0.5))
                beside(room, bed, side, high, uniform(0.4, 0.5));  // night stands
        }
    }
    const int other =
        side >= 0 && chance(0.6) ? opposite(side) : std::uniform_int_distribution<>(0, 3)(rng_);
    const double depth = uniform(0.55, 0.65);
    solidAgainstWall(room, other, uniform(1.0, 2.4), depth, 0.0);  // a wardrobe
    if (chance(0.4)) {
        const int s = std::uniform_int_distribution<>(0, 3)(rng_);
        Box d;
        if (againstWall(room, s, uniform(1.0, 1.4), 0.6, 0.0, d)) {
            desk(d);
            chairInFront(d, s);
        }
    }
    if (chance(0.3))
        cornerPlant(room);
}

void FurniturePlacer::bathroom(const FloorRoom& room) {
    const Box& f = room.floor;
    const std::vector<int> sides = sidesByLength(f);
    if (lengthOf(f, sides[0]) >= 1.7 && chance(0.6)) {
        const double depth = uniform(0.7, 0.8), length = uniform(1.6, 1.75);
        solidAgainstWall(  // a bathtub
            room, sides[static_cast<std::size_t>(std::uniform_int_distribution<>(0, 1)(rng_))],
            length, depth, 0.0);
    }
    solidAgainstWall(room, std::uniform_int_distribution<>(0, 3)(rng_), 0.38, 0.62,
                     0.0);  // a toilet
    const int s = std::uniform_int_distribution<>(0, 3)(rng_);
    Box basin;
    if (chance(0.5)) {  // a vanity unit
        const double depth = uniform(0.45, 0.5);
        solidAgainstWall(room, s, uniform(0.5, 0.9), depth, 0.0);
    } else if (againstWall(room, s, 0.2, 0.2, 0.15, basin))  // a basin on a pedestal
        disc({0.5 * (basin.xMin + basin.xMax), 0.5 * (basin.yMin + basin.yMax)}, 0.1);
    if (chance(0.3))  // a washing machine
        solidAgainstWall(room, std::uniform_int_distribution<>(0, 3)(rng_), 0.6, 0.6, 0.0);
}

void FurniturePlacer::hall(const FloorRoom& room) {
    const std::vector<int> sides = sidesByLength(room.floor);
    const int n = std::uniform_int_distribution<>(0, 2)(rng_);
    for (int k = 0; k < n; ++k) {
        const double depth = uniform(0.3, 0.4), length = uniform(0.6, 1.2);
        solidAgainstWall(  // a shoe cabinet, a coat stand, a chest of drawers
            room, sides[static_cast<std::size_t>(std::uniform_int_distribution<>(0, 1)(rng_))],
            length, depth, 0.0);
    }
}

}  // namespace toposlam::simulation
