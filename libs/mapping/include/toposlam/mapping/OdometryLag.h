#pragma once
// Odometry that stalls, then catches up. Some logs carry the odometry in each laser line as the
// last odometry message received (CARMEN's FLASER lines): when those messages stop for a few
// scans the odometry reads the same while the robot moves on, and when they come back the
// first increments hold the motion of the stall on top of their own (mit-csail: 0.49 m and
// 29 deg in one scan where the robot turned 10). The stall itself does little harm
// (registration finds the motion from a standstill prediction), but a catch-up increment is a
// prediction off by the backlog, and ICP started there can settle at the wrong heading where
// nothing in range says otherwise (mit-csail with its laser clipped at 5.6 m: one scan 20 deg
// off, a corridor mapped at an angle).
//
// A stall is an increment of exactly zero while the robot moved at the last scan (a robot
// standing still reads zero too, but registers no motion). After a stall an increment that is
// longer, or turns farther, than the robot's last registered motion by more than kAgreeDistance
// or kAgreeAngle is taken for catching up, and that motion is predicted instead; the first
// increment within the margins ends it, and so do kMaxCatchUpScans scans. (Only more motion
// counts: a backlog adds to the step, while a robot slowing down reads less, and at a third of
// mit-csail's scan rate its turn rate changes by 15 deg between two scans.)
#include <mrpt/poses/CPose2D.h>

namespace toposlam::mapping {

class OdometryLag {
  public:
    /// Registered motion above this (m, rad) per scan is the robot moving, not noise.
    static constexpr double kMovedDistance = 0.02;
    static constexpr double kMovedAngle = 0.0175;  // 1 deg
    /// An odometry increment at most this much (m, rad) longer or farther turned than the last
    /// registered motion has caught up.
    static constexpr double kAgreeDistance = 0.2;
    static constexpr double kAgreeAngle = 0.1745;  // 10 deg
    /// Scans after a stall at most taken for catching up.
    static constexpr int kMaxCatchUpScans = 5;

    /// `increment`: the odometry since the last scan (robot frame of the last scan, m, rad);
    /// `lastMotion`: the motion registered at the last scan (same frame). True when the
    /// increment is taken for the odometry catching up: predict `lastMotion` instead.
    bool catchingUp(const mrpt::poses::CPose2D& increment, const mrpt::poses::CPose2D& lastMotion);

  private:
    bool stalled_ = false;  ///< the last increment was a stall
    int catchUpLeft_ = 0;   ///< scans still taken for catching up
};

}  // namespace toposlam::mapping
