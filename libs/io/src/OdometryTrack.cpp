#include "OdometryTrack.h"

namespace toposlam::io {

std::optional<mrpt::poses::CPose2D> OdometryTrack::at(double time) {
    // Keep only the last sample at or before `time` and everything after it.
    while (samples_.size() >= 2 && samples_[1].time <= time)
        samples_.pop_front();
    if (samples_.empty() || samples_.front().time > time)
        return std::nullopt;
    const Sample& a = samples_.front();
    if (samples_.size() == 1 || a.time == time)
        return a.pose;
    // Linear interpolation of the motion between the bracketing samples, in a's frame.
    const Sample& b = samples_[1];
    const double s = (time - a.time) / (b.time - a.time);
    const mrpt::poses::CPose2D motion = b.pose - a.pose;
    return a.pose + mrpt::poses::CPose2D(s * motion.x(), s * motion.y(), s * motion.phi());
}

}  // namespace toposlam::io
