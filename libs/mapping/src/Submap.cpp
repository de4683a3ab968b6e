#include <toposlam/mapping/Submap.h>

namespace toposlam::mapping {

Submap::Submap(std::size_t anchor, const matching::LineMapOptions& options)
    : anchor_(anchor), map_(options) {}

void Submap::insert(const Keyframe& kf, const mrpt::poses::CPose2D& robotInSubmap) {
    keyframes_.push_back(kf.id);
    map_.insertSurface(kf.surface, robotInSubmap + kf.sensorOnRobot);
}

void Submap::clear() {
    keyframes_.clear();
    map_.clear();
}

void Submap::finish() {
    map_ = matching::LineMap(map_.options());
    finished_ = true;
}

}  // namespace toposlam::mapping
