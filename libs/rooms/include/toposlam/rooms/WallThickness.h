#pragma once
// How thick the building's walls are, measured on the map: from every free cell next to an
// obstacle, walk into the obstacle along the clearance gradient (across the wall, whatever its
// direction on the grid) to the next free cell. The obstacle runs between two free cells are
// wall thicknesses (or furniture plus the wall it stands against); walls are by far the longest
// obstacle boundary of a building, so the thicknesses its walls have are the frequent ones.
// Outer walls (unknown space behind them) give no run, nor, on SLAM grids, runs through unknown
// cells only (no cell the laser hit: streaks between beams, the ragged edge of the mapped space).
//
// TopoSLAM uses it to tell a wall end from a cabinet, a fridge or a shelf standing against a
// wall (DoorFilters, wall-end test): a wall end is as thick as the building's walls are.
//
// Thicknesses are counted in steps of kThicknessStep (5 cm), or of a cell on coarser grids: a
// run measured across a wall varies by a cell with the wall's angle to the grid, and walls of
// one building differ by a few centimetres. Counted per cell on a finer grid, the same building
// would have its walls spread over twice the steps and a 2.5 cm tolerance instead of 5 cm.
#include <toposlam/rooms/DoorSearchPaths.h>
#include <toposlam/rooms/FreeSpaceBinarizer.h>

#include <cmath>
#include <vector>

namespace toposlam::rooms {

class WallThickness {
  public:
    /// Measures the runs of space.free (`clearance` of space.free) up to `maxThickness` m.
    void measure(const FreeSpace& space, const Clearance& clearance, double maxThickness);
    /// Forgets the measurement: every thickness up to the maximum is a wall's.
    void clear() { counts_.clear(); }

    /// m: the step thicknesses are counted in (a cell on coarser grids).
    static constexpr double kThicknessStep = 0.05;

    /// Whether an obstacle `cells` thick is as thick as this building's walls: within a step
    /// of the most frequent run, or itself at least `minShare` as frequent as it (counts
    /// summed over a step either way). Without a measurement (or no run): true.
    bool isWallThickness(double cells, double minShare = 0.25) const;
    /// The most frequent run (cells, a whole number of steps); 0 without one.
    int mostFrequent() const { return static_cast<int>(std::lround(mode_ * stepCells_)); }
    /// Runs per thickness step (index = obstacle cells crossed / cells per step, rounded).
    const std::vector<double>& counts() const { return counts_; }

  private:
    double smoothed(int step) const;
    std::vector<double> counts_;
    int mode_ = 0;          // in steps
    double stepCells_ = 1;  // cells per step: 1 on grids of 5 cm cells or coarser
};

}  // namespace toposlam::rooms
