#pragma once
// Which cells of an occupancy grid are free, occupied or unknown, and how far each free cell is
// from anything that is not free. The tour planner, the moving obstacles and the tests use it to
// keep robots and people away from walls.
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <toposlam/simulation/GridGeometry.h>

#include <cstdint>
#include <vector>

namespace toposlam::simulation {

/// Classification of a cell by its p(free) (MRPT convention: 0 = occupied, 1 = free,
/// 0.5 = unknown). The defaults leave a symmetric band around 0.5 for unknown cells, so maps
/// built by SLAM (free cells seen a few times) and maps drawn as images both classify well.
struct OccupancyThresholds {
    double occupiedBelow = 0.4;  ///< p(free) < this: occupied
    double freeAbove = 0.6;      ///< p(free) > this: free; anything in between is unknown
};

enum class CellClass : std::uint8_t { Free, Occupied, Unknown };

class ClearanceMap {
  public:
    explicit ClearanceMap(const mrpt::maps::COccupancyGridMap2D& map,
                          const OccupancyThresholds& thresholds = {});

    const GridGeometry& geometry() const { return geometry_; }
    /// Cells outside the map are Unknown.
    CellClass cellClass(int cx, int cy) const;
    bool isFree(int cx, int cy) const { return cellClass(cx, cy) == CellClass::Free; }
    std::size_t freeCellCount() const { return freeCells_; }

    /// Distance (m) from the centre of cell (cx, cy) to the nearest cell that is not free
    /// (occupied, unknown, or outside the map), measured to that cell's nearest edge for
    /// axis-aligned neighbours (centre distance - resolution/2; at most 0.21 * resolution too
    /// large for diagonal ones). 0 for cells that are not free and outside the map.
    float clearance(int cx, int cy) const {
        return geometry_.contains(cx, cy) ? clearance_[geometry_.index(cx, cy)] : 0.0f;
    }
    /// Clearance of the cell containing `p` (world frame, m).
    float clearanceAt(const mrpt::math::TPoint2D& p) const {
        return clearance(geometry_.cellX(p.x), geometry_.cellY(p.y));
    }
    /// Raw per-cell clearance, indexed by GridGeometry::index.
    const std::vector<float>& clearances() const { return clearance_; }

  private:
    GridGeometry geometry_;
    std::vector<CellClass> classes_;
    std::vector<float> clearance_;
    std::size_t freeCells_ = 0;
};

}  // namespace toposlam::simulation
