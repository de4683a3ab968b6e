#include "FlatFloorPlan.h"

#include "GeneratedBuilding.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace toposlam::simulation {

namespace {

using mrpt::math::TPoint2D;

constexpr double kMinRoomSide = 1.8;  ///< m: no room is narrower (a bathroom, a box room)
constexpr double kJambMargin = 0.08;  ///< m: least wall left between a door and a corner
constexpr double kMinDoor = 0.7;      ///< m

/// One piece of the partition: a room's floor (between wall faces), or the corner of the
/// bounding rectangle that an L-shaped flat leaves outside.
struct Piece {
    Box floor;
    bool outside = false;
};

/// Where two floors face each other across one wall.
struct SharedWall {
    std::size_t a = 0, b = 0;  ///< pieces
    bool vertical = false;     ///< the wall runs north-south (its centre line is x = line)
    double line = 0;           ///< m, the wall's centre line
    double from = 0, to = 0;   ///< m, the stretch both floors face, along the wall
    double length() const { return to - from; }
};

class FlatBuilder {
  public:
    FlatBuilder(unsigned seed, const FloorPlanGeneratorOptions& o) : rng_(seed), o_(o) {}

    GeneratedFloorPlan build(unsigned seed);

  private:
    double uniform(double a, double b) {
        return a >= b ? a : std::uniform_real_distribution<>(a, b)(rng_);
    }
    bool chance(double p) { return uniform(0, 1) < p; }
    /// Splits piece i by a wall across x (vertical = true: the wall runs north-south) or y,
    /// centred `at` m from the piece's low edge; the high part is appended as a new piece.
    void split(std::size_t i, bool vertical, double at);
    void cutCorner(double width, double depth);
    void partition(double width, double depth);
    std::vector<SharedWall> sharedWalls() const;
    void assignKinds(const std::vector<SharedWall>& walls);
    void connect(const std::vector<SharedWall>& walls);
    bool addDoor(const SharedWall& w, double width);
    double doorWidth(std::size_t a, std::size_t b);
    bool isSmall(std::size_t piece) const {
        return kind_[piece] == "bathroom" || kind_[piece] == "storage";
    }

    std::mt19937 rng_;
    FloorPlanGeneratorOptions o_;
    FloorPlan plan_;
    double tOuter_ = 0.2, tInner_ = 0.1;
    std::vector<Piece> pieces_;
    std::vector<std::string> kind_;  ///< per piece
    std::vector<int> room_;          ///< FloorRoom id per piece (0: outside)
    std::map<std::string, int> kinds_;
};

void FlatBuilder::split(std::size_t i, bool vertical, double at) {
    const Box f = pieces_[i].floor;
    const double h = tInner_ / 2;
    Piece high = pieces_[i];
    if (vertical) {
        const double x = f.xMin + at;
        plan_.addWall({x, f.yMin}, {x, f.yMax}, tInner_);
        pieces_[i].floor.xMax = x - h;
        high.floor.xMin = x + h;
    } else {
        const double y = f.yMin + at;
        plan_.addWall({f.xMin, y}, {f.xMax, y}, tInner_);
        pieces_[i].floor.yMax = y - h;
        high.floor.yMin = y + h;
    }
    pieces_.push_back(high);
}

// An L-shaped flat: a corner of the rectangle, 2.5 m or more each way, is not part of it.
void FlatBuilder::cutCorner(double width, double depth) {
    const double bw = std::max(2.5, uniform(0.25, 0.4) * width);
    const double bh = std::max(2.5, uniform(0.3, 0.55) * depth);
    const bool east = chance(0.5), north = chance(0.5);
    split(0, true, east ? width - bw : bw);
    const std::size_t column = east ? 1 : 0;
    split(column, false, north ? depth - bh : bh);
    pieces_[north ? pieces_.size() - 1 : column].outside = true;
}

void FlatBuilder::partition(double width, double depth) {
    pieces_ = {Piece{{0, 0, width, depth}, false}};
    if (chance(0.35))
        cutCorner(width, depth);
    double area = 0;
    for (const Piece& p : pieces_)
        area += p.outside ? 0 : p.floor.area();
    const int target = std::clamp(static_cast<int>(std::lround(area / uniform(11, 17))), 4, 10);
    const double least = 2 * kMinRoomSide + tInner_;
    for (;;) {
        const auto rooms = std::count_if(pieces_.begin(), pieces_.end(),
                                         [](const Piece& p) { return !p.outside; });
        if (rooms >= target)
            break;
        // The largest piece that still holds two rooms.
        std::size_t best = pieces_.size();
        for (std::size_t i = 0; i < pieces_.size(); ++i) {
            const Box& f = pieces_[i].floor;
            if (pieces_[i].outside || std::max(f.xMax - f.xMin, f.yMax - f.yMin) < least)
                continue;
            if (best == pieces_.size() || f.area() > pieces_[best].floor.area())
                best = i;
        }
        if (best == pieces_.size())
            break;
        const Box& f = pieces_[best].floor;
        const double w = f.xMax - f.xMin, h = f.yMax - f.yMin;
        bool vertical = w > 1.25 * h ? true : h > 1.25 * w ? false : chance(0.5);
        if ((vertical ? w : h) < least)
            vertical = !vertical;
        const double length = vertical ? w : h;
        const double lo = kMinRoomSide + tInner_ / 2, hi = length - kMinRoomSide - tInner_ / 2;
        double at = 0;
        if (chance(0.3)) {  // a narrow strip at one end: a bathroom, a box room, a hall
            const double strip = uniform(kMinRoomSide, 2.6) + tInner_ / 2;
            at = chance(0.5) ? strip : length - strip;
        } else {
            at = uniform(0.35, 0.65) * length;
        }
        split(best, vertical, std::clamp(at, lo, hi));
    }
}

std::vector<SharedWall> FlatBuilder::sharedWalls() const {
    std::vector<SharedWall> out;
    const double h = tInner_ / 2;
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
        for (std::size_t j = 0; j < pieces_.size(); ++j) {
            if (i == j || pieces_[i].outside || pieces_[j].outside)
                continue;
            const Box &a = pieces_[i].floor, &b = pieces_[j].floor;
            SharedWall w{i, j, false, 0, 0, 0};
            if (std::abs(a.xMax + tInner_ - b.xMin) < 1e-6) {  // b east of a
                w.vertical = true;
                w.line = a.xMax + h;
                w.from = std::max(a.yMin, b.yMin);
                w.to = std::min(a.yMax, b.yMax);
            } else if (std::abs(a.yMax + tInner_ - b.yMin) < 1e-6) {  // b north of a
                w.line = a.yMax + h;
                w.from = std::max(a.xMin, b.xMin);
                w.to = std::min(a.xMax, b.xMax);
            } else {
                continue;
            }
            if (w.length() > 0.5)
                out.push_back(w);
        }
    }
    return out;
}

void FlatBuilder::assignKinds(const std::vector<SharedWall>& walls) {
    kind_.assign(pieces_.size(), "bedroom");
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
        if (pieces_[i].outside)
            kind_[i] = "outside";
        else
            order.push_back(i);
    }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return pieces_[a].floor.area() < pieces_[b].floor.area();
    });
    const std::size_t living = order.back();
    kind_[living] = "living";
    int bathrooms = 0;
    for (std::size_t i : order) {
        const Box& f = pieces_[i].floor;
        const double shortSide = std::min(f.xMax - f.xMin, f.yMax - f.yMin);
        const double longSide = std::max(f.xMax - f.xMin, f.yMax - f.yMin);
        if (i == living)
            continue;
        if (shortSide < 2.1 && longSide >= 3.5 && f.area() < 12)
            kind_[i] = "hall";
        else if (f.area() < 4)
            kind_[i] = "storage";
        else if (f.area() <= 8 && (bathrooms == 0 || (bathrooms == 1 && chance(0.6))))
            kind_[i] = "bathroom", ++bathrooms;
    }
    if (bathrooms == 0) {  // every flat has one: the smallest room that can be one
        for (std::size_t i : order) {
            if (kind_[i] == "bedroom") {
                kind_[i] = "bathroom";
                break;
            }
        }
    }
    // A kitchen next to the living room, most of the time.
    std::vector<std::size_t> kitchens;
    for (const SharedWall& w : walls) {
        const std::size_t other = w.a == living ? w.b : w.b == living ? w.a : pieces_.size();
        if (other < pieces_.size() && kind_[other] == "bedroom" &&
            pieces_[other].floor.area() >= 5 && pieces_[other].floor.area() <= 15 &&
            std::find(kitchens.begin(), kitchens.end(), other) == kitchens.end())
            kitchens.push_back(other);
    }
    if (!kitchens.empty() && chance(0.9))
        kind_[kitchens[std::uniform_int_distribution<std::size_t>(0, kitchens.size() - 1)(rng_)]] =
            "kitchen";
    for (std::size_t i : order) {
        if (kind_[i] == "bedroom" && chance(0.25))
            kind_[i] = "office";  // a study
    }
}

double FlatBuilder::doorWidth(std::size_t a, std::size_t b) {
    if (isSmall(a) || isSmall(b))
        return uniform(0.7, 0.8);
    const bool living = kind_[a] == "living" || kind_[b] == "living";
    const bool kitchen = kind_[a] == "kitchen" || kind_[b] == "kitchen";
    const bool hall = kind_[a] == "hall" || kind_[b] == "hall";
    if (living && kitchen && chance(0.4))
        return uniform(1.4, 2.4);  // an open kitchen
    if (living && hall && chance(0.25))
        return uniform(1.2, 1.5);  // a double door
    return uniform(0.8, 0.9);
}

bool FlatBuilder::addDoor(const SharedWall& w, double width) {
    width = std::min(width, w.length() - 2 * kJambMargin);
    if (width < kMinDoor)
        return false;
    const double first = w.from + kJambMargin, last = w.to - kJambMargin - width;
    double start = 0;
    if (chance(0.45)) {  // a hand's width from a corner, as most doors are
        const double gap = uniform(kJambMargin, 0.25);
        start = std::clamp(chance(0.5) ? w.from + gap : w.to - gap - width, first, last);
    } else {
        start = uniform(first, last);
    }
    const TPoint2D a = w.vertical ? TPoint2D{w.line, start} : TPoint2D{start, w.line};
    const TPoint2D b =
        w.vertical ? TPoint2D{w.line, start + width} : TPoint2D{start + width, w.line};
    plan_.addDoor(a, b, room_[w.a], room_[w.b]);
    return true;
}

void FlatBuilder::connect(const std::vector<SharedWall>& walls) {
    std::vector<char> reached(pieces_.size(), 0);
    const auto living =
        static_cast<std::size_t>(std::find(kind_.begin(), kind_.end(), "living") - kind_.begin());
    reached[living] = 1;
    std::vector<char> joined(walls.size(), 0);
    // People reach rooms from the hall or the living room, and walk through a bathroom or a
    // box room to nowhere.
    const auto hub = [&](std::size_t p) {
        return kind_[p] == "hall" ? 3 : kind_[p] == "living" ? 2 : isSmall(p) ? 0 : 1;
    };
    for (;;) {
        int bestHub = -1;
        std::vector<std::size_t> choices;
        for (std::size_t k = 0; k < walls.size(); ++k) {
            const SharedWall& w = walls[k];
            if (reached[w.a] == reached[w.b] || w.length() < kMinDoor + 2 * kJambMargin)
                continue;
            const int h = hub(reached[w.a] ? w.a : w.b);
            if (h > bestHub)
                bestHub = h, choices.clear();
            if (h == bestHub)
                choices.push_back(k);
        }
        if (choices.empty())
            break;
        const std::size_t k =
            choices[std::uniform_int_distribution<std::size_t>(0, choices.size() - 1)(rng_)];
        const SharedWall& w = walls[k];
        if (addDoor(w, doorWidth(w.a, w.b)))
            joined[k] = 1;
        reached[w.a] = reached[w.b] = 1;
    }
    // Now and then a second way between neighbours (rarely into a bathroom).
    for (std::size_t k = 0; k < walls.size(); ++k) {
        const SharedWall& w = walls[k];
        if (joined[k] || !reached[w.a] || !reached[w.b])
            continue;
        if (chance(isSmall(w.a) || isSmall(w.b) ? 0.03 : 0.12))
            addDoor(w, uniform(0.8, 0.9));
    }
}

GeneratedFloorPlan FlatBuilder::build(unsigned seed) {
    const double width = uniform(o_.minFlatWidth, o_.maxFlatWidth);
    const double depth = uniform(o_.minFlatDepth, o_.maxFlatDepth);
    const detail::WallThicknesses thicknesses = detail::drawWallThicknesses(rng_);
    tOuter_ = thicknesses.outer;
    tInner_ = thicknesses.inner;
    detail::addOuterWalls(plan_, width, depth, tOuter_);
    partition(width, depth);
    std::vector<SharedWall> walls = sharedWalls();
    assignKinds(walls);
    // A piece that no wall long enough for a door joins to the living room (a sliver between
    // T-junctions, rare) is left out of the flat, as a shaft would be.
    std::vector<char> reachable(pieces_.size(), 0);
    reachable[static_cast<std::size_t>(std::find(kind_.begin(), kind_.end(), "living") -
                                       kind_.begin())] = 1;
    for (bool grew = true; grew;) {
        grew = false;
        for (const SharedWall& w : walls) {
            if (w.length() >= kMinDoor + 2 * kJambMargin && reachable[w.a] != reachable[w.b])
                reachable[w.a] = reachable[w.b] = 1, grew = true;
        }
    }
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
        if (!reachable[i])
            pieces_[i].outside = true, kind_[i] = "outside";
    }
    walls.erase(
        std::remove_if(walls.begin(), walls.end(),
                       [&](const SharedWall& w) { return !reachable[w.a] || !reachable[w.b]; }),
        walls.end());
    room_.assign(pieces_.size(), 0);
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
        if (pieces_[i].outside)
            continue;
        ++kinds_[kind_[i]];
        room_[i] = plan_.addRoom(kind_[i] + " " + std::to_string(plan_.rooms().size() + 1),
                                 kind_[i], pieces_[i].floor);
    }
    connect(walls);

    GeneratedFloorPlan out;
    out.seed = seed;
    out.unfurnished = plan_;
    out.outerWallThickness = tOuter_;
    out.innerWallThickness = tInner_;
    out.groundTruthRoom.assign(plan_.rooms().size() + 1, 0);
    for (const FloorRoom& r : plan_.rooms())
        out.groundTruthRoom[static_cast<std::size_t>(r.id)] = ++out.roomCount;
    const std::size_t furniture = o_.furnish ? detail::furnishRooms(plan_, rng_) : 0;
    out.plan = plan_;
    const bool lShaped =
        std::any_of(pieces_.begin(), pieces_.end(), [](const Piece& p) { return p.outside; });
    char line[256];
    std::snprintf(line, sizeof line,
                  "seed %u: %s flat %.1f x %.1f m, %zu rooms, %zu doors, %zu furniture pieces;",
                  seed, lShaped ? "L-shaped" : "rectangular", width, depth, plan_.rooms().size(),
                  plan_.doors().size(), furniture);
    out.summary = line + detail::kindCounts(kinds_);
    return out;
}

}  // namespace

GeneratedFloorPlan generateFlatPlan(unsigned seed, const FloorPlanGeneratorOptions& options) {
    return FlatBuilder(seed, options).build(seed);
}

}  // namespace toposlam::simulation
