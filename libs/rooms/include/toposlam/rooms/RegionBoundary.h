#pragma once
// How much of each region's boundary is open to unobserved space outside the building
// (deviation, SLAM grids). A room is enclosed by walls; on a SLAM grid its walls are occupied
// cells (and the holes where the laser grazed them), and the unknown shadows of furniture
// inside the building are enclosed by what the laser saw around them. Unknown space away from
// every occupied cell (FreeSpace::noWall) that reaches the edge of the mapped area is outside:
// never observed, joined to what lies beyond the map. A region whose boundary is mostly such
// outside is not known to be enclosed: the pocket between two cabinets whose back the laser
// never saw, cut off at its mouth by a door whose jambs are the cabinets' faces (with unknown
// behind them they look like the building's edge). The minimum-area filter merges such a
// region through its door like a too-small one (DoorFilters::Options::maxOpenBoundary). Drawn
// maps without unknown cells have no open boundary.
#include <toposlam/rooms/ConnectedRuns.h>
#include <toposlam/rooms/FreeSpaceBinarizer.h>
#include <toposlam/rooms/RegionPartition.h>

#include <opencv2/core/mat.hpp>

#include <vector>

namespace toposlam::rooms {

class RegionBoundary {
  public:
    /// Counts, per region of `partition` (computed on space.free, same image), the 4-neighbour
    /// contacts of its cells with non-free cells: open (unknown cells of FreeSpace::noWall
    /// 4-connected to the edge of the image: outside) or closed (all others: occupied cells,
    /// wall holes, shadows inside the building). Door cuts (free cells of no region) count as
    /// neither.
    void measure(const FreeSpace& space, const RegionPartition& partition);

    /// Cell edges, index = region label ([0] unused); all zero when the map has no unknown
    /// cell away from the walls (FreeSpace::noWall empty: nothing is measured).
    const std::vector<int>& closed() const { return closed_; }
    const std::vector<int>& open() const { return open_; }

  private:
    std::vector<int> closed_, open_;
    cv::Mat unobserved_, components_;  // scratch, reused from call to call
    ConnectedRuns runs_;
    std::vector<unsigned char> outside_;
};

}  // namespace toposlam::rooms
