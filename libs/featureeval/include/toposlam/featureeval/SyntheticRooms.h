#pragma once
// Random furnished rooms with exact geometry, the scenes of benchmark B1 and of the feature
// tests: a room outline (rectangle, possibly with an L-notch and a 45-degree chamfer, rotated
// at random), rectangular and triangular furniture kept clear of the walls and of each other,
// optional round pillars, and sensor poses in the free space. Everything in metres, world
// frame. The same seed gives the same scene.
#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/simulation/PolygonWorld.h>

#include <random>
#include <vector>

namespace toposlam::featureeval {

using Polygon = std::vector<mrpt::math::TPoint2D>;

struct SyntheticScene {
    /// Closed polygons, counter-clockwise: [0] is the room outline (seen from inside), the
    /// rest furniture (seen from outside).
    std::vector<Polygon> polygons;
    std::vector<simulation::Disc> discs;
    /// Sensor poses (world frame) in the free space.
    std::vector<mrpt::poses::CPose2D> poses;

    /// The ray-casting world of the scene.
    simulation::PolygonWorld world() const;
};

struct SyntheticRoomOptions {
    double minWidth = 4, maxWidth = 10;  ///< m, room extent before notches
    double minDepth = 3, maxDepth = 8;   ///< m
    double notchProbability = 0.5;       ///< L-shaped room
    double chamferProbability = 0.4;     ///< one corner cut at 45 deg (two 135-deg corners)
    int minFurniture = 2, maxFurniture = 6;
    double triangleProbability = 0.25;  ///< furniture piece is a triangle, not a box
    double clearance = 0.3;             ///< m between furniture, walls and pillars
    int maxPillars = 1;                 ///< round pillars (0..maxPillars)
    int posesPerRoom = 5;
    double poseClearance = 0.4;  ///< m from any obstacle
};

/// One random scene.
SyntheticScene makeSyntheticRoom(std::mt19937& rng, const SyntheticRoomOptions& options = {});

/// True when p is inside the closed polygon (even-odd rule).
bool insidePolygon(const Polygon& poly, const mrpt::math::TPoint2D& p);

}  // namespace toposlam::featureeval
