#pragma once
// A local map of consecutive keyframes, in the robot frame of its first keyframe (its anchor):
// the line map that scans are registered against. The graph SLAM keeps two active submaps
// overlapping by half (as Cartographer does): every keyframe goes into both, scans are matched
// against the older, fuller one, and a submap that has its share of keyframes is finished
// (its line map goes to the next new submap, which reuses its memory; its keyframes stay in the
// graph). Because the content is in the anchor's frame, the submap moves rigidly with the
// anchor when the graph is optimised; after an optimisation the active submaps are rebuilt
// from their keyframes' new poses.
#include <mrpt/poses/CPose2D.h>
#include <toposlam/mapping/Keyframe.h>
#include <toposlam/matching/LineMap.h>

#include <cstddef>
#include <vector>

namespace toposlam::mapping {

class Submap {
  public:
    Submap(std::size_t anchor, const matching::LineMapOptions& options);
    /// The same, its line map in `reused`'s memory (a finished submap's, see finish()), reset.
    Submap(std::size_t anchor, matching::LineMap&& reused);

    /// Keyframe id whose robot frame is this submap's frame.
    std::size_t anchor() const { return anchor_; }
    const std::vector<std::size_t>& keyframes() const { return keyframes_; }
    const matching::LineMap& map() const { return map_; }

    /// Adds keyframe `kf`, whose ROBOT pose in the submap frame is `robotInSubmap`.
    void insert(const Keyframe& kf, const mrpt::poses::CPose2D& robotInSubmap);
    /// Empties the line map (for a rebuild: insert the keyframes again); keeps nothing.
    void clear();
    /// Gives up the line map, returned for a new submap to reuse; the keyframe list stays.
    matching::LineMap finish();
    bool finished() const { return finished_; }

  private:
    std::size_t anchor_;
    std::vector<std::size_t> keyframes_;
    matching::LineMap map_;
    bool finished_ = false;
};

}  // namespace toposlam::mapping
