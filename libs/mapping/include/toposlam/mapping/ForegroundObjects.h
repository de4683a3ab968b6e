#pragma once
// Small objects close to the laser that stand in front of what lies behind them: people,
// mostly. A person walking just ahead of the robot keeps its place relative to the robot, so in
// the submap it stands where the next scan sees it again, and ICP fitted to it takes back the
// robot's step. ScanRegistration re-registers such a scan without these objects.
//
// An object is a run of consecutive valid readings, each within breakDistance of the last
// (sensor frame, m); it is in the foreground when its nearest reading is within maxRange, its
// first and last readings are at most maxWidth apart, and the readings just beside it (if
// valid) lie at least inFront farther. On full-circle scans an object across the first and
// last beams is never in the foreground (its halves see each other as neighbours).
#include <toposlam/matching/PolarScan.h>

#include <cstddef>
#include <vector>

namespace toposlam::mapping {

struct ForegroundObjectOptions {
    double maxRange = 1.5;        ///< m from the laser to the object's nearest reading, at most
    double maxWidth = 0.8;        ///< m between its first and last readings, at most
    double breakDistance = 0.15;  ///< m: consecutive readings farther apart start a new object
    double inFront = 0.2;         ///< m: the readings beside it at least this much farther
};

class ForegroundObjects {
  public:
    /// Writes `scan` without its foreground objects to `out` (its storage reused) and returns
    /// how many readings that left out; 0 leaves `out` untouched.
    std::size_t remove(const matching::PolarScan& scan, const ForegroundObjectOptions& options,
                       matching::PolarScan& out);
    /// Whether `scan` shows any foreground object (remove() > 0), without copying it.
    static bool any(const matching::PolarScan& scan, const ForegroundObjectOptions& options);

  private:
    /// Calls found(first, last) with the beams of each foreground object in order, while it
    /// returns true.
    template <typename Found>
    static void forEachObject(const matching::PolarScan& scan,
                              const ForegroundObjectOptions& options, Found&& found);

    std::vector<float> ranges_;  // reused between calls
    std::vector<char> valid_;
};

}  // namespace toposlam::mapping
