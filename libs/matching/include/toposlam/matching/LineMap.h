#pragma once
// A map of local lines built from many scans, for point-to-line registration against a local
// map instead of a single scan (PointToLineIcp::refineOnMap). Every map point carries the unit
// normal of the surface it lies on (fitLocalLine of its scan). Repeated observations of the
// same surface are fused into the point already there (running mean of position and normal),
// so walls seen from twenty poses stay one thin line of points rather than a noisy band.
// A lookup grid stores, for every cell within `radius` of a map point, the map point nearest to
// that cell's centre: association is two array reads per point and ICP iteration, with no
// search tree and no allocation. The grid is tiled: only tiles near map points exist, so a
// laser reaching 80 m does not make the grid 160 m square (a small directory of tiles grows as
// points arrive; the tiles are allocated once and reused after clear()).
// All coordinates are in the map's own frame (m).
#include <mrpt/poses/CPose2D.h>
#include <toposlam/matching/PolarScan.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace toposlam::matching {

struct LineMapPoint {
    float x = 0, y = 0;    ///< m, map frame
    float nx = 0, ny = 0;  ///< unit normal, towards the sensors that saw it
    float weight = 0;      ///< observations fused into it
    /// Scans that saw a surface here (LineMapOptions::confirmDistance; one scan counts once): a
    /// wall has one from every pose that had it in view; a person walking along with the robot
    /// is somewhere else in every scan, so its points keep one.
    std::uint32_t views = 1;
    std::uint32_t lastScan = 0;  ///< the insertScan / insertSurface call that last saw it
    /// The insertScan / insertSurface call that made it (observations fused into it later do
    /// not change it): which scan first showed the map this surface.
    std::uint32_t firstScan = 0;
    /// Scans whose beams passed through this place (LineMap::carve): free when they looked.
    std::uint32_t seenThrough = 0;
    /// Seen through as often as seen: something that moved away (a person), not a wall, which
    /// every scan that looks its way sees, and none sees through.
    bool moved() const { return seenThrough >= views; }
};

/// A reading with the normal of its local line, in the sensor frame of its scan (m): what a
/// scan contributes to any line map, whatever pose it is inserted at.
struct SurfacePoint {
    double x = 0, y = 0;
    double nx = 0, ny = 0;
};

struct LineMapOptions {
    double resolution = 0.05;  ///< m, lookup cell size
    double radius = 0.4;       ///< m, largest association distance the lookup supports
    /// m: a new observation within this distance of a map point with a similar normal is
    /// fused into it instead of added.
    double fuseDistance = 0.05;
    /// m: a point counts one more view (LineMapPoint::views) when a point of another scan
    /// lands this close to it, fused or not (a door frame seen from two poses a few cm apart).
    double confirmDistance = 0.1;
    double maxRange = 20.0;        ///< m, farther readings are not inserted
    double maxJoinDistance = 0.3;  ///< m, fitLocalLine's jump distance
    /// m: a keyframe's beam that reaches this much beyond a map point (with both neighbouring
    /// beams) saw through it (carve; mapping::Submap carves its map with every keyframe's
    /// scan). 0 = no carving.
    double carveMargin = 0;
};

class LineMap {
  public:
    explicit LineMap(const LineMapOptions& options = {});

    const LineMapOptions& options() const { return options_; }
    /// Empties the map (keeps its memory). The lattice stays where the first point put it.
    void clear();
    /// Empties the map and its lattice: the map then behaves exactly as a new one, but keeps
    /// its memory (a new submap's map reuses a finished one's: no regrowing, no page faults).
    void reset();
    /// Adds every valid reading of `scan` that has a local line, seen from `sensorPose` (the
    /// scan's sensor in the map frame).
    void insertScan(const PolarScan& scan, const mrpt::poses::CPose2D& sensorPose);
    /// The same from the scan's surface points (surfacePoints), e.g. computed once for a scan
    /// that goes into several maps.
    void insertSurface(const std::vector<SurfacePoint>& points,
                       const mrpt::poses::CPose2D& sensorPose);
    /// Counts a view through (LineMapPoint::seenThrough) every map point from index `first` on
    /// that `scan`, seen from `sensorPose` (map frame), saw through: its beam towards the point
    /// and both neighbours are valid and reach `margin` (m) or more beyond it. Two neighbours,
    /// so that a beam grazing the edge of an object does not clear its corner.
    void carve(const PolarScan& scan, const mrpt::poses::CPose2D& sensorPose, std::size_t first,
               double margin);
    /// The map points `scan`, seen from `sensorPose` (map frame), would see through, as carve()
    /// judges them, counted and not recorded: free space that a registration at that pose
    /// claims where the map has a surface.
    std::size_t countSeenThrough(const PolarScan& scan, const mrpt::poses::CPose2D& sensorPose,
                                 double margin) const;
    /// Adds one point (fused into a close one with a similar normal).
    void insert(const LineMapPoint& p);

    /// The map point nearest to (x, y)'s lookup cell, or nullptr when none is within radius.
    const LineMapPoint* nearest(double x, double y) const {
        // Cell indices on the lattice, counted from the directory's first tile.
        const long cx = long(std::floor((x - latticeX_) * inverseResolution_)) - firstCellX_;
        const long cy = long(std::floor((y - latticeY_) * inverseResolution_)) - firstCellY_;
        if (cx < 0 || cy < 0 || cx >= tilesX_ * kTile || cy >= tilesY_ * kTile)
            return nullptr;
        const std::uint32_t tile = tileOf_[std::size_t((cy / kTile) * tilesX_ + cx / kTile)];
        if (tile == kNone)
            return nullptr;
        const std::uint32_t i =
            cells_[std::size_t(tile) * kTileCells + std::size_t((cy % kTile) * kTile + cx % kTile)]
                .point;
        return i == kNone ? nullptr : &points_[i];
    }

    std::size_t size() const { return points_.size(); }
    /// insertScan / insertSurface calls since the map was made or cleared.
    std::uint32_t scans() const { return scans_; }
    /// Lookup cells in use (whole tiles near map points): the grid's memory is this times 8 B.
    std::size_t lookupCells() const { return tilesUsed_ * kTileCells; }
    const std::vector<LineMapPoint>& points() const { return points_; }

  private:
    static constexpr std::uint32_t kNone = 0xffffffffu;
    /// Calls seen(i) for every point i from `first` on that `scan` at `sensorPose` sees
    /// through (carve, countSeenThrough).
    template <typename Seen>
    void forEachSeenThrough(const PolarScan& scan, const mrpt::poses::CPose2D& sensorPose,
                            std::size_t first, double margin, Seen&& seen) const;
    static constexpr long kTile = 32;  ///< cells along a tile's side (1.6 m at 5 cm)
    static constexpr std::size_t kTileCells = std::size_t(kTile * kTile);
    struct Cell {
        std::uint32_t point = kNone;
        /// Squared distance of that point to the cell centre (m^2); infinite when there is none.
        float distance2 = std::numeric_limits<float>::infinity();
    };
    /// Makes the tile directory cover the box [minX, maxX] x [minY, maxY] +- radius (tiles
    /// themselves are made when a point is stamped into them).
    void cover(double minX, double minY, double maxX, double maxY);
    /// The tile at directory position (tx, ty), made (empty) if it does not exist yet.
    Cell* tileAt(long tx, long ty);
    /// Writes point i into every cell within radius whose current point is farther.
    void stamp(std::uint32_t i);

    LineMapOptions options_;
    std::vector<LineMapPoint> points_;
    std::vector<SurfacePoint> surface_;     // insertScan's scratch
    std::vector<LineMapPoint> inMapFrame_;  // insertSurface's scratch
    /// Tile k holds cells_[k * kTileCells, (k + 1) * kTileCells), row by row.
    std::vector<Cell> cells_;
    std::size_t tilesUsed_ = 0;
    /// tilesX_ x tilesY_ directory, row by row: the tile index, or kNone where none is made.
    std::vector<std::uint32_t> tileOf_;
    long tilesX_ = 0, tilesY_ = 0;
    /// Cell (i, j) of the lattice has its corner at (latticeX_ + i * resolution, latticeY_ +
    /// j * resolution): the lattice is anchored at the first point inserted, so the cells (and
    /// every lookup) are the same however the directory grew. The directory starts at lattice
    /// cell (firstCellX_, firstCellY_), a whole number of tiles from the anchor.
    double latticeX_ = 0, latticeY_ = 0;
    long firstCellX_ = 0, firstCellY_ = 0;
    double inverseResolution_ = 20;
    long stampRadius_ = 8;          ///< radius in cells
    std::vector<float> columnDx2_;  ///< stamp()'s scratch: squared x offsets of its columns (m^2)
    std::uint32_t scans_ = 0;
};

/// Calls visit(mapPoint) for every valid reading of `scan`, seen from SENSOR pose `sensor` (map
/// frame), that lies within `distance` (m) of the local line of its nearest map point (any point
/// within the map's radius): the readings a pose explains, and the map points that explain them.
template <typename Visit>
void forEachReadingOnSurface(const LineMap& map, const PolarScan& scan,
                             const mrpt::poses::CPose2D& sensor, double distance, Visit&& visit) {
    const double c = std::cos(sensor.phi()), s = std::sin(sensor.phi());
    for (std::size_t i = 0; i < scan.size(); ++i) {
        if (!scan.valid(i))
            continue;
        const mrpt::math::TPoint2D& p = scan.point(i);
        const double qx = sensor.x() + c * p.x - s * p.y, qy = sensor.y() + s * p.x + c * p.y;
        const LineMapPoint* m = map.nearest(qx, qy);
        if (m && std::abs(m->nx * (qx - m->x) + m->ny * (qy - m->y)) <= distance)
            visit(*m);
    }
}

/// The readings of `scan` within options.maxRange that have a local line (fitLocalLine with
/// options.maxJoinDistance, reaching as far as the scan's noise asks), with its normal, in the
/// sensor frame; `out` is replaced.
void surfacePoints(const PolarScan& scan, const LineMapOptions& options,
                   std::vector<SurfacePoint>& out);

}  // namespace toposlam::matching
