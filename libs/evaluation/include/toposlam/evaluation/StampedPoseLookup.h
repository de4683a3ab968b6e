#pragma once
// Finds the pose a trajectory has at a given time stamp. Relation files and trajectories refer
// to the same laser scans by their time stamps, printed with 5 or 6 decimals, so stamps are
// compared with a tolerance (1e-5 s by default: half a unit of the 5th decimal is 5e-6 s,
// while scans are at least ~10 ms apart).
#include <toposlam/io/Trajectory.h>

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace toposlam::evaluation {

class StampedPoseLookup {
  public:
    /// Default stamp tolerance, s.
    static constexpr double kDefaultTolerance = 1e-5;

    /// Indexes `trajectory` by stamp; it need not be sorted (old CARMEN logs have stamps that go
    /// backwards). `tolerance` (s) is the largest accepted |stamp difference|.
    explicit StampedPoseLookup(const io::Trajectory2D& trajectory,
                               double tolerance = kDefaultTolerance);

    /// Index (into the trajectory) of the pose whose stamp is nearest to `stamp`, if that one
    /// is within the tolerance; nullopt otherwise. Ties go to the earlier pose in the file.
    std::optional<std::size_t> find(double stamp) const;

    double tolerance() const { return tolerance_; }

  private:
    std::vector<std::pair<double, std::size_t>> byStamp_;  ///< (stamp, index), sorted
    double tolerance_;
};

}  // namespace toposlam::evaluation
