#pragma once
// Step 6 of the virtual-door method (sec. 1.5): the free space is cut along the door lines and
// split into 4-connected regions by connected-component analysis (ConnectedRuns). The door filters
// of step 5 (adjacency, minimum area) and the final rooms are read off this partition.
#include <toposlam/rooms/ConnectedRuns.h>
#include <toposlam/rooms/VirtualDoorDetector.h>

#include <opencv2/core/mat.hpp>

#include <utility>
#include <vector>

namespace toposlam::rooms {

class RegionPartition {
  public:
    RegionPartition() = default;
    /// `free`: CV_8U, non-zero = free. Each door is cut as an 8-connected digital line from
    /// jamb to jamb, which 4-connected regions cannot cross.
    RegionPartition(const cv::Mat& free, const std::vector<VirtualDoor>& doors) {
        compute(free, doors);
    }
    /// Same as the constructor; the images of a previous call are reused.
    void compute(const cv::Mat& free, const std::vector<VirtualDoor>& doors);
    /// The labels, for the caller to take over (e.g. to turn them into room ids in place).
    cv::Mat& mutableLabels() { return labels_; }

    /// CV_32S: 0 = not free or on a door cut; regions are 1..regionCount(), in raster order of
    /// their first cell.
    const cv::Mat& labels() const { return labels_; }
    int regionCount() const { return regionCount_; }
    /// Cells per region; index = label, [0] unused.
    const std::vector<int>& areas() const { return areas_; }
    /// The regions' cells run by run (ConnectedRuns::Run::label = region), in raster order.
    const std::vector<ConnectedRuns::Run>& regionRuns() const { return runs_.runs(); }
    /// The free cells on the door cuts (in no region), in raster order.
    const std::vector<cv::Point>& cutCells() const { return cutCells_; }
    std::size_t doorCount() const { return touching_.size(); }
    /// The regions 4-adjacent to the cut of door `door` with their number of contacts, most
    /// contacts first. A door that separates something touches at least two.
    const std::vector<std::pair<int, int>>& regionsAt(std::size_t door) const {
        return touching_[door];
    }

  private:
    cv::Mat open_;  // scratch
    ConnectedRuns runs_;
    std::vector<cv::Point> cutCells_;
    cv::Mat labels_;
    int regionCount_ = 0;
    std::vector<int> areas_;
    std::vector<std::vector<std::pair<int, int>>> touching_;
};

}  // namespace toposlam::rooms
