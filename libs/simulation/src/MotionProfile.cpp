#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>
#include <toposlam/simulation/MotionProfile.h>

#include <algorithm>
#include <cmath>

namespace toposlam::simulation {

using mrpt::math::TPoint2D;

void MotionOptions::declare(config::OptionsSchema& s) {
    s.real("max_speed", maxSpeed, "m/s", "speed limit of the robot").above(0);
    s.angle("max_turn_rate", maxTurnRate, "turn rate limit of the robot", "deg/s").above(0);
    s.real("scan_distance", scanDistance, "m",
           "the logger records a scan each scan_distance driven")
        .above(0);
    s.angle("scan_angle", scanAngle, "... or scan_angle_deg turned since the last one").above(0);
    s.real("start_time", startTime, "s", "Unix time of the first scan").atLeast(0);
}

namespace {

/// Accumulates small motions and records a pose whenever the logger's thresholds are reached.
class ScanRecorder {
  public:
    ScanRecorder(const MotionOptions& o, io::Trajectory2D& out) : o_(o), out_(out) {}

    void start(double x, double y, double yaw) {
        pose_ = {x, y, yaw};
        record();
    }
    /// Moves to (x, y, yaw), taking the time the speed limits require.
    void moveTo(double x, double y, double yaw) {
        const double ds = std::hypot(x - pose_.x, y - pose_.y);
        const double dyaw = std::abs(mrpt::math::wrapToPi(yaw - pose_.phi));
        t_ += std::max(ds / o_.maxSpeed, dyaw / o_.maxTurnRate);
        pose_ = {x, y, mrpt::math::wrapToPi(yaw)};
        driven_ += ds;
        turned_ += dyaw;
        if (driven_ >= o_.scanDistance - 1e-9 || turned_ >= o_.scanAngle - 1e-9)
            record();
    }
    /// Turns on the spot to `yaw` in steps small enough for the angle threshold.
    void turnTo(double yaw) {
        const double delta = mrpt::math::wrapToPi(yaw - pose_.phi);
        const int steps = static_cast<int>(std::ceil(std::abs(delta) / mrpt::DEG2RAD(1.0)));
        const double start = pose_.phi;
        for (int k = 1; k <= steps; ++k)
            moveTo(pose_.x, pose_.y, start + delta * k / steps);
    }
    void finish() {
        if (driven_ > 0 || turned_ > 0)
            record();
    }
    double yaw() const { return pose_.phi; }

  private:
    void record() {
        // Elapsed time is summed from 0: added step by step to a Unix time (~1.7e9 s, exact
        // to 2.4e-7 s) it would lose microseconds.
        out_.push_back({o_.startTime + t_, pose_});
        driven_ = turned_ = 0;
    }
    const MotionOptions& o_;
    io::Trajectory2D& out_;
    mrpt::math::TPose2D pose_;
    double t_ = 0, driven_ = 0, turned_ = 0;
};

double heading(const TPoint2D& a, const TPoint2D& b) {
    return std::atan2(b.y - a.y, b.x - a.x);
}

}  // namespace

io::Trajectory2D driveLegs(const std::vector<std::vector<TPoint2D>>& legs, double initialYaw,
                           const MotionOptions& options) {
    io::Trajectory2D out;
    ScanRecorder rec(options, out);
    bool started = false;
    std::vector<TPoint2D> leg;
    for (const auto& rawLeg : legs) {
        // Drop repeated points: a zero-length segment has no heading.
        leg.clear();
        for (const TPoint2D& p : rawLeg) {
            if (leg.empty() || std::hypot(p.x - leg.back().x, p.y - leg.back().y) > 1e-9) {
                leg.push_back(p);
            }
        }
        if (leg.empty())
            continue;
        if (!started) {
            rec.start(leg.front().x, leg.front().y, initialYaw);
            started = true;
        }
        if (leg.size() < 2)
            continue;
        // Heading at each vertex: the segment's direction, averaged over the two segments that
        // meet at inner vertices (the tangent of the smooth curve).
        rec.turnTo(heading(leg[0], leg[1]));
        for (std::size_t i = 1; i < leg.size(); ++i) {
            const double in = heading(leg[i - 1], leg[i]);
            double yaw = in;
            if (i + 1 < leg.size()) {
                yaw = in + 0.5 * mrpt::math::wrapToPi(heading(leg[i], leg[i + 1]) - in);
            }
            rec.moveTo(leg[i].x, leg[i].y, yaw);
        }
    }
    rec.finish();
    return out;
}

}  // namespace toposlam::simulation
