#include <toposlam/simulation/FloorPlanGenerator.h>

#include "FlatFloorPlan.h"
#include "GeneratedBuilding.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <random>

namespace toposlam::simulation {

namespace {

using mrpt::math::TPoint2D;

// A block of rooms: a row of rooms along a corridor (inner faces), the corridor on its north or
// south side.
struct Block {
    Box box;
    bool corridorNorth = true;
    int corridor = 0;  ///< the corridor room its doors open into
};

class Builder {
  public:
    Builder(unsigned seed, const FloorPlanGeneratorOptions& o) : rng_(seed), o_(o) {}

    GeneratedFloorPlan build(unsigned seed);

  private:
    double uniform(double a, double b) { return std::uniform_real_distribution<>(a, b)(rng_); }
    bool chance(double p) { return uniform(0, 1) < p; }
    void layoutCorridors(double width, double depth, std::vector<Block>& blocks);
    double layoutRing(double width, std::vector<Block>& blocks);
    void fillBlock(const Block& b);
    int addRoomInRow(const Block& b, double x0, double x1, const std::string& kind);
    void doorToCorridor(const Block& b, double x0, double x1, int room, const std::string& kind);
    void partitionStubs(const Block& b, double x0, double x1, double doorX0, double doorX1);
    double doorWidth(const std::string& kind);

    std::mt19937 rng_;
    FloorPlanGeneratorOptions o_;
    FloorPlan plan_;
    double tOuter_ = 0.2, tInner_ = 0.1;
    std::map<std::string, int> kinds_;
};

double Builder::doorWidth(const std::string& kind) {
    if ((kind == "open plan" || kind == "lab") && chance(0.4))
        return uniform(1.5, 1.8);  // double door
    if (kind == "meeting" || kind == "kitchen" || kind == "open plan" || kind == "lab")
        return uniform(0.9, 1.2);
    return uniform(0.8, 1.0);
}

void Builder::layoutCorridors(double width, double depth, std::vector<Block>& blocks) {
    const double cw = uniform(o_.minCorridor, o_.maxCorridor);
    const double y0 =
        uniform(std::max(4.0, 0.3 * depth), std::min(depth - 4.0 - cw, 0.7 * depth - cw));
    const double y1 = y0 + cw;
    const int corridor = plan_.addRoom("corridor", "corridor", {0, y0, width, y1});
    // A branch corridor to the north and/or south outer wall (T or crossing), or none.
    const int branch = std::uniform_int_distribution<>(0, 3)(rng_);  // 0 none, 1 N, 2 S, 3 both
    const double bw = uniform(o_.minCorridor, o_.maxCorridor);
    const double bx0 = uniform(0.3 * width, 0.7 * width - bw), bx1 = bx0 + bw;
    const double h = tInner_ / 2;
    for (const bool north : {true, false}) {
        const bool hasBranch = branch == 3 || (north ? branch == 1 : branch == 2);
        // `north`: the blocks north of the corridor, whose corridor side is their south.
        const double wallY = north ? y1 + h : y0 - h;
        const double blockY0 = north ? y1 + tInner_ : 0, blockY1 = north ? depth : y0 - tInner_;
        if (!hasBranch) {
            plan_.addWall({0, wallY}, {width, wallY}, tInner_);
            blocks.push_back({{0, blockY0, width, blockY1}, !north, corridor});
            continue;
        }
        const double farY = north ? depth : 0;
        plan_.addRoom("corridor branch", "corridor",
                      north ? Box{bx0, y1, bx1, depth} : Box{bx0, 0, bx1, y0});
        plan_.addWall({0, wallY}, {bx0 - h, wallY}, tInner_);
        plan_.addWall({bx1 + h, wallY}, {width, wallY}, tInner_);
        plan_.addWall({bx0 - h, wallY}, {bx0 - h, farY}, tInner_);
        plan_.addWall({bx1 + h, wallY}, {bx1 + h, farY}, tInner_);
        blocks.push_back({{0, blockY0, bx0 - tInner_, blockY1}, !north, corridor});
        blocks.push_back({{bx1 + tInner_, blockY0, width, blockY1}, !north, corridor});
    }
}

// A corridor ring: corridors along the south and north sides joined along the west and east
// outer walls, rows of rooms between them and the outer walls and two rows back to back in the
// middle (a loop to drive round, and rooms that look alike all along it). Returns the depth.
double Builder::layoutRing(double width, std::vector<Block>& blocks) {
    const double cw = uniform(o_.minCorridor, o_.maxCorridor);
    const double outerSouth = uniform(4.0, 7.0), innerSouth = uniform(4.0, 7.0);
    const double innerNorth = uniform(4.0, 7.0), outerNorth = uniform(4.0, 7.0);
    const double t = tInner_, h = tInner_ / 2;
    const double yS0 = outerSouth + t, yS1 = yS0 + cw;  // the south corridor
    const double yMiddle = yS1 + t + innerSouth + h;    // the wall between the middle rows
    const double yN0 = yMiddle + h + innerNorth + t, yN1 = yN0 + cw;
    const double depth = yN1 + t + outerNorth;
    const int south = plan_.addRoom("corridor south", "corridor", {0, yS0, width, yS1});
    const int north = plan_.addRoom("corridor north", "corridor", {0, yN0, width, yN1});
    plan_.addRoom("corridor west", "corridor", {0, yS1, cw, yN0});
    plan_.addRoom("corridor east", "corridor", {width - cw, yS1, width, yN0});
    plan_.addWall({0, yS0 - h}, {width, yS0 - h}, t);
    plan_.addWall({0, yN1 + h}, {width, yN1 + h}, t);
    // The middle block: its outline, and the wall between its two rows.
    const double x0 = cw + h, x1 = width - cw - h;
    plan_.addWall({x0, yS1 + h}, {x1, yS1 + h}, t);
    plan_.addWall({x0, yN0 - h}, {x1, yN0 - h}, t);
    plan_.addWall({x0, yS1 + h}, {x0, yN0 - h}, t);
    plan_.addWall({x1, yS1 + h}, {x1, yN0 - h}, t);
    plan_.addWall({x0, yMiddle}, {x1, yMiddle}, t);
    blocks.push_back({{0, 0, width, yS0 - t}, true, south});
    blocks.push_back({{cw + t, yS1 + t, width - cw - t, yMiddle - h}, false, south});
    blocks.push_back({{cw + t, yMiddle + h, width - cw - t, yN0 - t}, true, north});
    blocks.push_back({{0, yN1 + t, width, depth}, false, north});
    return depth;
}

int Builder::addRoomInRow(const Block& b, double x0, double x1, const std::string& kind) {
    ++kinds_[kind];
    return plan_.addRoom(kind + " " + std::to_string(plan_.rooms().size() + 1), kind,
                         {x0, b.box.yMin, x1, b.box.yMax});
}

void Builder::doorToCorridor(const Block& b, double x0, double x1, int room,
                             const std::string& kind) {
    const double wallY = b.corridorNorth ? b.box.yMax + tInner_ / 2 : b.box.yMin - tInner_ / 2;
    const double w = std::min(doorWidth(kind), x1 - x0 - 0.7);
    const double a = uniform(x0 + 0.35, x1 - 0.35 - w);
    plan_.addDoor({a, wallY}, {a + w, wallY}, room, b.corridor);
    // Large rooms often have a second door.
    if (x1 - x0 > 9 && chance(0.5)) {
        const double w2 = doorWidth(kind);
        const double c = a + w < 0.5 * (x0 + x1) ? uniform(0.5 * (x0 + x1), x1 - 0.35 - w2)
                                                 : uniform(x0 + 0.35, 0.5 * (x0 + x1) - w2);
        plan_.addDoor({c, wallY}, {c + w2, wallY}, room, b.corridor);
    }
    if ((kind == "open plan" || kind == "lab") && b.box.yMax - b.box.yMin > 5 && chance(0.6))
        partitionStubs(b, x0, x1, a, a + w);
}

// Partition walls from the back wall towards the corridor that stop 2-3.5 m short of it: one
// room with openings wider than any door inside it.
void Builder::partitionStubs(const Block& b, double x0, double x1, double doorX0, double doorX1) {
    const double depth = b.box.yMax - b.box.yMin;
    const int n = chance(0.5) ? 2 : 1;
    for (int k = 0; k < n; ++k) {
        const double x = uniform(x0 + 2.5, x1 - 2.5);
        if (x > doorX0 - 1.0 && x < doorX1 + 1.0)
            continue;
        const double gap = uniform(2.0, 3.5);
        const double length = depth - gap;
        if (length < 1.0)
            continue;
        const double back = b.corridorNorth ? b.box.yMin : b.box.yMax;
        const double end = b.corridorNorth ? back + length : back - length;
        plan_.addWall({x, back}, {x, end}, tInner_);
    }
}

void Builder::fillBlock(const Block& b) {
    const double depth = b.box.yMax - b.box.yMin;
    double x = b.box.xMin;
    int previous = 0;
    bool previousSplit = true;
    while (b.box.xMax - x > 1e-6) {
        const double r = uniform(0, 1);
        std::string kind = r < 0.55 ? "office" : r < 0.8 ? "meeting" : "open plan";
        double w = kind == "office"    ? uniform(2.8, 4.2)
                   : kind == "meeting" ? uniform(3.5, 6.5)
                                       : uniform(7.0, 14.0);
        if (b.box.xMax - x - w < 2.8)
            w = b.box.xMax - x;  // the last room takes the rest
        if (kind == "office" && w > 5)
            kind = "meeting";
        if (kind == "meeting" && w > 8)
            kind = "open plan";
        if (kind == "meeting") {
            const double k = uniform(0, 1);
            kind = k < 0.5 ? "meeting" : k < 0.75 ? "kitchen" : "storage";
        }
        if (kind == "open plan" && chance(0.3))
            kind = "lab";
        const double x1 = x + w;
        // A deep block: sometimes a second room behind the first, reached through it.
        const bool split = depth > 8.5 && kind != "open plan" && kind != "lab" && chance(0.5);
        Block front = b;
        if (split) {
            const double d = uniform(4.0, std::min(6.0, depth - 3.0));
            const double wallY =
                b.corridorNorth ? b.box.yMax - d - tInner_ / 2 : b.box.yMin + d + tInner_ / 2;
            plan_.addWall({x, wallY}, {x1, wallY}, tInner_);
            Block back = b;
            if (b.corridorNorth) {
                front.box.yMin = wallY + tInner_ / 2;
                back.box.yMax = wallY - tInner_ / 2;
            } else {
                front.box.yMax = wallY - tInner_ / 2;
                back.box.yMin = wallY + tInner_ / 2;
            }
            const int backRoom = addRoomInRow(back, x, x1, chance(0.5) ? "storage" : "office");
            const int frontRoom = addRoomInRow(front, x, x1, kind);
            const double dw = uniform(0.8, 1.0);
            const double a = uniform(x + 0.35, x1 - 0.35 - dw);
            plan_.addDoor({a, wallY}, {a + dw, wallY}, frontRoom, backRoom);
            doorToCorridor(b, x, x1, frontRoom, kind);
            previous = 0;
        } else {
            const int room = addRoomInRow(b, x, x1, kind);
            doorToCorridor(b, x, x1, room, kind);
            // A door to the neighbour in the row, now and then.
            if (previous != 0 && !previousSplit && depth > 3.0 && chance(0.15)) {
                const double dw = uniform(0.8, 1.0);
                const double a = uniform(b.box.yMin + 0.5, b.box.yMax - 0.5 - dw);
                plan_.addDoor({x - tInner_ / 2, a}, {x - tInner_ / 2, a + dw}, previous, room);
            }
            previous = room;
        }
        previousSplit = split;
        if (x1 < b.box.xMax - 1e-6)
            plan_.addWall({x1 + tInner_ / 2, b.box.yMin}, {x1 + tInner_ / 2, b.box.yMax}, tInner_);
        x = std::min(b.box.xMax, x1 + tInner_);
    }
}

GeneratedFloorPlan Builder::build(unsigned seed) {
    const bool ring = o_.style == BuildingStyle::Ring;
    const double width =
        ring ? uniform(o_.minRingWidth, o_.maxRingWidth) : uniform(o_.minWidth, o_.maxWidth);
    double depth = ring ? 0.0 : uniform(o_.minDepth, o_.maxDepth);
    const detail::WallThicknesses walls = detail::drawWallThicknesses(rng_);
    tOuter_ = walls.outer;
    tInner_ = walls.inner;
    std::vector<Block> blocks;
    if (ring) {
        depth = layoutRing(width, blocks);  // the rows' depths make the building's
        detail::addOuterWalls(plan_, width, depth, tOuter_);
    } else {
        detail::addOuterWalls(plan_, width, depth, tOuter_);
        layoutCorridors(width, depth, blocks);
    }
    for (const Block& b : blocks)
        fillBlock(b);

    GeneratedFloorPlan out;
    out.seed = seed;
    out.unfurnished = plan_;
    out.outerWallThickness = tOuter_;
    out.innerWallThickness = tInner_;
    out.groundTruthRoom.assign(plan_.rooms().size() + 1, 0);
    for (const FloorRoom& r : plan_.rooms()) {
        out.groundTruthRoom[static_cast<std::size_t>(r.id)] =
            r.kind == "corridor" ? 0 : ++out.roomCount;
    }
    const int corridorRoom = ++out.roomCount;
    for (const FloorRoom& r : plan_.rooms()) {
        if (r.kind == "corridor")
            out.groundTruthRoom[static_cast<std::size_t>(r.id)] = corridorRoom;
    }
    const std::size_t pieces = o_.furnish ? detail::furnishRooms(plan_, rng_) : 0;
    out.plan = plan_;
    char line[256];
    std::snprintf(line, sizeof line,
                  "seed %u: %.1f x %.1f m, %zu room boxes, %zu doors, %zu furniture pieces;", seed,
                  width, depth, plan_.rooms().size(), plan_.doors().size(), pieces);
    out.summary = line + detail::kindCounts(kinds_);
    return out;
}

}  // namespace

GeneratedFloorPlan generateFloorPlan(unsigned seed, const FloorPlanGeneratorOptions& options) {
    if (options.style == BuildingStyle::Flat)
        return generateFlatPlan(seed, options);
    return Builder(seed, options).build(seed);
}

}  // namespace toposlam::simulation
