#pragma once
// Furnishes the rooms of a FloorPlan the way people furnish them (FloorPlanGenerator): by the
// room's kind, desks against walls with their chairs, shelves and cabinets along walls, plants
// in corners, meeting tables with chairs all round, kitchen counters, rows of lab benches,
// islands of desks in open-plan areas, a few things along corridor walls; in flats a sofa with
// its coffee table and a TV unit across the room, a dining table, beds with their heads to a
// wall and night stands beside them, wardrobes, bathtubs, toilets and wash basins. Furniture never
// blocks a door (a zone as wide as the door plus 0.3 m and 1.1 m deep on both sides stays
// clear, as people keep it) and pieces do not overlap each other or the walls; otherwise
// positions, sizes and gaps (to walls, between desks) are random.
//
// What is drawn is what a laser about 0.3 m above the floor sees: tables by their legs, desks
// by their legs, a drawer pedestal or two side panels, chairs by their central column, plants
// and bins as discs, cabinets, shelves, counters and sofas as solid blocks.
#include <toposlam/simulation/FloorPlan.h>

#include <cstddef>
#include <random>
#include <vector>

namespace toposlam::simulation {

class FurniturePlacer {
  public:
    /// Furniture goes into `plan`; `rng` draws every random choice.
    FurniturePlacer(FloorPlan& plan, std::mt19937& rng);

    /// Furnishes `room` by its kind: "office", "meeting", "kitchen", "storage", "lab",
    /// "open plan", "corridor", "living", "bedroom", "bathroom", "hall" (other kinds get a few
    /// pieces along the walls).
    void furnish(const FloorRoom& room);

    /// Pieces of furniture placed so far (a desk with its legs is one piece).
    std::size_t pieces() const { return pieces_; }

  private:
    double uniform(double a, double b);
    bool chance(double p);
    /// Whether `footprint` lies in `room`'s floor, clear of walls, door zones and furniture.
    bool fits(const FloorRoom& room, const Box& footprint) const;
    /// A footprint `length` along wall `side` (0 south, 1 north, 2 west, 3 east) of `room`,
    /// `depth` deep, `gap` from the wall face, at a random place along it; false when none of a
    /// few tries fits. On success the footprint is reserved.
    bool againstWall(const FloorRoom& room, int side, double length, double depth, double gap,
                     Box& out);
    bool reserve(const FloorRoom& room, const Box& footprint);
    /// One solid piece (a cabinet, a wardrobe, a bathtub) placed as againstWall places it;
    /// false when it does not fit.
    bool solidAgainstWall(const FloorRoom& room, int side, double length, double depth, double gap);

    void solid(const Box& b);
    void legs(const Box& b);
    void desk(const Box& b);
    void chair(const mrpt::math::TPoint2D& p);
    void disc(const mrpt::math::TPoint2D& p, double radius);
    /// A chair in front of a desk placed against wall `side`.
    void chairInFront(const Box& desk, int side);
    void cornerPlant(const FloorRoom& room);
    void shelves(const FloorRoom& room, int count);

    void office(const FloorRoom& room);
    void meeting(const FloorRoom& room);
    void kitchen(const FloorRoom& room);
    void storage(const FloorRoom& room);
    void lab(const FloorRoom& room);
    void openPlan(const FloorRoom& room);
    void corridor(const FloorRoom& room);
    void living(const FloorRoom& room);
    void bedroom(const FloorRoom& room);
    void bathroom(const FloorRoom& room);
    void hall(const FloorRoom& room);
    /// A solid piece `size` across, against the wall `side` right beside `next` (a bed's
    /// night stand, an armchair by the sofa), on its low or high end.
    void beside(const FloorRoom& room, const Box& next, int side, bool high, double size);

    FloorPlan& plan_;
    std::mt19937& rng_;
    std::vector<Box> walls_, doorZones_, doorways_, placed_;
    std::size_t pieces_ = 0;
};

}  // namespace toposlam::simulation
