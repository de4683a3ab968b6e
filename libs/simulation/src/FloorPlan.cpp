#include <toposlam/io/JsonFile.h>
#include <toposlam/simulation/FloorPlan.h>
#include <toposlam/simulation/GridGeometry.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace toposlam::simulation {

using mrpt::math::TPoint2D;

void FloorPlan::addWall(const TPoint2D& a, const TPoint2D& b, double thickness) {
    const bool horizontal = std::abs(a.y - b.y) < 1e-9;
    if (!horizontal && std::abs(a.x - b.x) > 1e-9) {
        throw std::invalid_argument("FloorPlan::addWall: walls must be axis-aligned");
    }
    const double h = thickness / 2;
    Box box;
    if (horizontal) {
        box = {std::min(a.x, b.x) - h, a.y - h, std::max(a.x, b.x) + h, a.y + h};
    } else {
        box = {a.x - h, std::min(a.y, b.y) - h, a.x + h, std::max(a.y, b.y) + h};
    }
    walls_.push_back({box, horizontal});
    maxWallThickness_ = std::max(maxWallThickness_, thickness);
    refreshOpenings();
}

void FloorPlan::refreshOpenings() {
    // Each opening: the jamb segment swept across the thickest wall it may cut.
    doorOpenings_.clear();
    const double h = maxWallThickness_ / 2 + 1e-6;
    for (const FloorDoor& d : doors_) {
        if (std::abs(d.jambA.y - d.jambB.y) < 1e-9) {
            doorOpenings_.push_back({std::min(d.jambA.x, d.jambB.x), d.jambA.y - h,
                                     std::max(d.jambA.x, d.jambB.x), d.jambA.y + h});
        } else {
            doorOpenings_.push_back({d.jambA.x - h, std::min(d.jambA.y, d.jambB.y), d.jambA.x + h,
                                     std::max(d.jambA.y, d.jambB.y)});
        }
    }
}

int FloorPlan::addRoom(const std::string& name, const std::string& kind, const Box& floor) {
    const int id = static_cast<int>(rooms_.size()) + 1;
    rooms_.push_back({id, name, kind, floor});
    return id;
}

int FloorPlan::addDoor(const TPoint2D& jambA, const TPoint2D& jambB, int roomA, int roomB) {
    const bool horizontal = std::abs(jambA.y - jambB.y) < 1e-9;
    if (!horizontal && std::abs(jambA.x - jambB.x) > 1e-9) {
        throw std::invalid_argument("FloorPlan::addDoor: doors must be axis-aligned");
    }
    const int id = static_cast<int>(doors_.size()) + 1;
    doors_.push_back(
        {id, jambA, jambB, std::hypot(jambB.x - jambA.x, jambB.y - jambA.y), roomA, roomB});
    refreshOpenings();
    return id;
}

void FloorPlan::addFurniture(const Box& box) {
    furnitureBoxes_.push_back(box);
}
void FloorPlan::addFurniture(const Disc& disc) {
    furnitureDiscs_.push_back(disc);
}

std::vector<Box> FloorPlan::wallPieces() const {
    std::vector<Box> pieces;
    for (const Wall& w : walls_) {
        // Cut the wall along its axis by every opening that crosses it.
        std::vector<std::pair<double, double>> solid{w.horizontal
                                                         ? std::make_pair(w.box.xMin, w.box.xMax)
                                                         : std::make_pair(w.box.yMin, w.box.yMax)};
        for (const Box& o : doorOpenings_) {
            const bool crosses = w.horizontal ? o.yMin <= w.box.yMin && o.yMax >= w.box.yMax &&
                                                    o.xMax > w.box.xMin && o.xMin < w.box.xMax
                                              : o.xMin <= w.box.xMin && o.xMax >= w.box.xMax &&
                                                    o.yMax > w.box.yMin && o.yMin < w.box.yMax;
            if (!crosses)
                continue;
            const double c0 = w.horizontal ? o.xMin : o.yMin, c1 = w.horizontal ? o.xMax : o.yMax;
            std::vector<std::pair<double, double>> next;
            for (const auto& [s0, s1] : solid) {
                if (c0 > s0)
                    next.push_back({s0, std::min(s1, c0)});
                if (c1 < s1)
                    next.push_back({std::max(s0, c1), s1});
            }
            solid = next;
        }
        for (const auto& [s0, s1] : solid) {
            if (s1 - s0 < 1e-9)
                continue;
            pieces.push_back(w.horizontal ? Box{s0, w.box.yMin, s1, w.box.yMax}
                                          : Box{w.box.xMin, s0, w.box.xMax, s1});
        }
    }
    return pieces;
}

Box FloorPlan::extent() const {
    Box e{1e300, 1e300, -1e300, -1e300};
    for (const Wall& w : walls_) {
        e = {std::min(e.xMin, w.box.xMin), std::min(e.yMin, w.box.yMin),
             std::max(e.xMax, w.box.xMax), std::max(e.yMax, w.box.yMax)};
    }
    return e;
}

bool FloorPlan::isSolid(const TPoint2D& p) const {
    for (const Box& b : furnitureBoxes_) {
        if (b.contains(p))
            return true;
    }
    for (const Disc& d : furnitureDiscs_) {
        if (std::hypot(p.x - d.centre.x, p.y - d.centre.y) <= d.radius)
            return true;
    }
    for (const Wall& w : walls_) {
        if (!w.box.contains(p))
            continue;
        const bool inOpening = std::any_of(doorOpenings_.begin(), doorOpenings_.end(),
                                           [&](const Box& o) { return o.contains(p); });
        if (!inOpening)
            return true;
    }
    return false;
}

int FloorPlan::roomAt(const TPoint2D& p) const {
    for (const FloorRoom& r : rooms_) {
        if (r.floor.contains(p))
            return r.id;
    }
    return 0;
}

mrpt::maps::COccupancyGridMap2D FloorPlan::rasterise(double resolution, double margin) const {
    const Box e = extent();
    mrpt::maps::COccupancyGridMap2D grid;
    grid.setSize(static_cast<float>(e.xMin - margin), static_cast<float>(e.xMax + margin),
                 static_cast<float>(e.yMin - margin), static_cast<float>(e.yMax + margin),
                 static_cast<float>(resolution), 0.5f);
    const GridGeometry g = GridGeometry::of(grid);
    for (int cy = 0; cy < g.sizeY; ++cy) {
        for (int cx = 0; cx < g.sizeX; ++cx) {
            const TPoint2D p = g.centre(cx, cy);
            const bool inDoorway = std::any_of(doorOpenings_.begin(), doorOpenings_.end(),
                                               [&](const Box& o) { return o.contains(p); });
            if (isSolid(p)) {
                grid.setCell(cx, cy, 0.0f);
            } else if (roomAt(p) != 0 || inDoorway) {
                grid.setCell(cx, cy, 1.0f);
            }
        }
    }
    return grid;
}

std::vector<std::uint8_t> FloorPlan::roomLabels(const mrpt::maps::COccupancyGridMap2D& grid) const {
    if (rooms_.size() > 255)
        throw std::length_error("FloorPlan: more than 255 rooms");
    const GridGeometry g = GridGeometry::of(grid);
    std::vector<std::uint8_t> labels(g.cellCount(), 0);
    for (int cy = 0; cy < g.sizeY; ++cy) {
        for (int cx = 0; cx < g.sizeX; ++cx) {
            labels[g.index(cx, cy)] = static_cast<std::uint8_t>(roomAt(g.centre(cx, cy)));
        }
    }
    return labels;
}

PolygonWorld FloorPlan::toPolygonWorld() const {
    PolygonWorld world;
    const auto addBox = [&](const Box& b) {
        world.addPolygon({{b.xMin, b.yMin}, {b.xMax, b.yMin}, {b.xMax, b.yMax}, {b.xMin, b.yMax}});
    };
    for (const Box& b : wallPieces())
        addBox(b);
    for (const Box& b : furnitureBoxes_)
        addBox(b);
    for (const Disc& d : furnitureDiscs_)
        world.addDisc(d);
    return world;
}

std::string FloorPlan::toJson(const mrpt::maps::COccupancyGridMap2D& grid,
                              const std::string& mapFile, const std::string& labelFile) const {
    const GridGeometry g = GridGeometry::of(grid);
    const auto point = [](double x, double y) {
        return io::Json::array({io::roundSignificant(x, 10), io::roundSignificant(y, 10)});
    };
    // The grid's geometry is stored in floats: written at float precision (0.05, not
    // 0.05000000075).
    const auto f = [](double v) { return io::roundSignificant(v, 7); };
    io::Json rooms = io::Json::array(), doors = io::Json::array();
    for (const FloorRoom& r : rooms_) {
        rooms.push_back({{"id", r.id},
                         {"name", r.name},
                         {"kind", r.kind},
                         {"min", point(r.floor.xMin, r.floor.yMin)},
                         {"max", point(r.floor.xMax, r.floor.yMax)},
                         {"area_m2", io::roundSignificant(r.floor.area(), 10)}});
    }
    for (const FloorDoor& d : doors_) {
        doors.push_back({{"id", d.id},
                         {"jambs", {point(d.jambA.x, d.jambA.y), point(d.jambB.x, d.jambB.y)}},
                         {"width", io::roundSignificant(d.width, 10)},
                         {"rooms", {d.roomA, d.roomB}}});
    }
    const io::Json labels = {
        {"image", labelFile},
        {"resolution", f(g.resolution)},
        {"origin", {f(g.xMin), f(g.yMin)}},
        {"width", g.sizeX},
        {"height", g.sizeY},
        {"pixel", "room id, 0 = no room (walls, doorways, outside); top row = highest y"}};
    return io::formatJson({{"frame", "map world frame, metres; yaw in radians"},
                           {"map", mapFile},
                           {"room_labels", labels},
                           {"rooms", rooms},
                           {"doors", doors}});
}

}  // namespace toposlam::simulation
