#pragma once
// Odometry samples of a log whose scans carry no odometry of their own (MRPT rawlogs in the
// observations format, CARMEN logs with RAWLASER lines), read at each scan's time.
#include <mrpt/poses/CPose2D.h>

#include <deque>
#include <optional>

namespace toposlam::io {

class OdometryTrack {
  public:
    /// Appends a sample (time in s; pose in the odometry frame: m, rad). Times are
    /// non-decreasing from call to call.
    void add(double time, const mrpt::poses::CPose2D& pose) { samples_.push_back({time, pose}); }

    bool empty() const { return samples_.empty(); }
    /// Time of the newest sample (s); only when !empty().
    double lastTime() const { return samples_.back().time; }

    /// The odometry at `time` (s): interpolated linearly, in the earlier sample's frame,
    /// between the bracketing samples; at or after the last sample that sample is held;
    /// before the first one, none. Times asked for are non-decreasing from call to call:
    /// samples before the one at or before `time` are dropped.
    std::optional<mrpt::poses::CPose2D> at(double time);

  private:
    struct Sample {
        double time;  // s
        mrpt::poses::CPose2D pose;
    };
    std::deque<Sample> samples_;
};

}  // namespace toposlam::io
