#pragma once
// An exact 2D vector world: wall segments, closed polygons (rooms, furniture) and discs
// (pillars, people), in metres, world frame. Ray casting is exact, so scans simulated here
// have known corners and segments: the ground truth of the feature and matching benchmarks.
#include <toposlam/simulation/RangeWorld.h>

#include <vector>

namespace toposlam::simulation {

struct WallSegment {
    mrpt::math::TPoint2D a, b;  ///< endpoints, m
};

struct Disc {
    mrpt::math::TPoint2D centre;  ///< m
    double radius = 0.25;         ///< m
};

class PolygonWorld : public RangeWorld {
  public:
    void addSegment(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b);
    /// Adds the edges of a closed polygon (the last vertex connects to the first).
    void addPolygon(const std::vector<mrpt::math::TPoint2D>& vertices);
    void addDisc(const Disc& disc);

    const std::vector<WallSegment>& segments() const { return segments_; }
    const std::vector<Disc>& discs() const { return discs_; }
    /// Mutable discs, to move obstacles between scans.
    std::vector<Disc>& discs() { return discs_; }

    double castRay(const mrpt::math::TPoint2D& origin, double angle,
                   double maxRange) const override;

  private:
    std::vector<WallSegment> segments_;
    std::vector<Disc> discs_;
};

}  // namespace toposlam::simulation
