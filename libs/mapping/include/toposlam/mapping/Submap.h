#pragma once
// A local map of consecutive keyframes, in the robot frame of its first keyframe (its anchor):
// the line map that scans are registered against. The graph SLAM keeps two active submaps
// overlapping by half (as Cartographer does): every keyframe goes into both, scans are matched
// against the older, fuller one, and a submap that has its share of keyframes is finished
// (its line map goes to the next new submap, which reuses its memory; its keyframes stay in the
// graph). Because the content is in the anchor's frame, the submap moves rigidly with the
// anchor when the graph is optimised; after an optimisation the active submaps are rebuilt
// from their keyframes' new poses.
// Parts: a keyframe placed by odometry alone (neither ICP nor the graph matcher could place its
// scan) may be off its true pose by more than the odometry's covariance says, and so is what
// later scans, registered on what it added, add after it: the map from there on is rigid to
// that keyframe, not to the anchor. Each such keyframe after the anchor starts a part of the
// submap; a scan registered on the submap is tied to the keyframe that starts the part most
// of its readings lie on (partHolding), and a scan that fits the part before it is tied to the
// anchor and exposes its error. (The graph matcher's placements start none: its covariance is a
// measurement's. Counting them too cost the real logs and people tours, benchmarks.md B3.)
// Free space (free_space_carving): where the beams of one keyframe passed through a place
// another keyframe saw a surface at, by 0.2 m or more, that surface has moved (a person who
// walked on). Each point counts the keyframes that saw through it, and ICP's first stage
// leaves out points seen through as often as seen (LineMapPoint::moved).
#include <mrpt/poses/CPose2D.h>
#include <toposlam/mapping/Keyframe.h>
#include <toposlam/matching/LineMap.h>
#include <toposlam/matching/PolarScan.h>

#include <cstddef>
#include <cstdint>
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

    /// Adds keyframe `kf`, whose ROBOT pose in the submap frame is `robotInSubmap`; a new part
    /// when it is placed by odometry alone (Keyframe::placedByOdometry) and not the anchor.
    void insert(const Keyframe& kf, const mrpt::poses::CPose2D& robotInSubmap);
    /// The keyframe that starts each part, the anchor first (one part: no keyframe after the
    /// anchor was placed by odometry alone).
    std::vector<std::size_t> partStarts() const;
    /// The keyframe that starts the part of the map holding the most readings of `scan` at
    /// SENSOR pose `sensor` (submap frame), counting those within `distance` (m) of the
    /// surface (the earlier part on a tie); the anchor when the submap has one part or when
    /// none lies on it.
    std::size_t partHolding(const matching::PolarScan& scan, const mrpt::poses::CPose2D& sensor,
                            double distance) const;
    /// Readings of `scan` at SENSOR pose `sensor` (submap frame) within `distance` (m) of the
    /// surface, counting only the map points of the parts before the newest one (all of them
    /// when the submap has one part): what a scan fits beyond the last keyframe placed by
    /// odometry alone and what later keyframes added on it, which may be as far off as it.
    std::size_t readingsBeforeNewestPart(const matching::PolarScan& scan,
                                         const mrpt::poses::CPose2D& sensor, double distance) const;
    /// Empties the line map (for a rebuild: insert the keyframes again); keeps nothing.
    void clear();
    /// Gives up the line map, returned for a new submap to reuse; the keyframe list stays.
    matching::LineMap finish();
    bool finished() const { return finished_; }

  private:
    std::size_t anchor_;
    std::vector<std::size_t> keyframes_;
    matching::LineMap map_;
    /// Parts after the first: the keyframe that starts it, and the first LineMap insertion
    /// (LineMapPoint::firstScan) that belongs to it.
    struct Part {
        std::size_t keyframe = 0;
        std::uint32_t firstScan = 0;
    };
    std::vector<Part> parts_;
    mutable std::vector<std::size_t> readingsPerPart_;  // partHolding's scratch
    /// Each keyframe's readings and sensor pose (submap frame), to carve the map with
    /// (LineMapOptions::carveMargin > 0).
    std::vector<std::pair<matching::PolarScan, mrpt::poses::CPose2D>> views_;
    bool finished_ = false;
};

}  // namespace toposlam::mapping
