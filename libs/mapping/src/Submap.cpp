#include <toposlam/mapping/Submap.h>

#include <utility>

namespace toposlam::mapping {

Submap::Submap(std::size_t anchor, const matching::LineMapOptions& options)
    : anchor_(anchor), map_(options) {}

Submap::Submap(std::size_t anchor, matching::LineMap&& reused)
    : anchor_(anchor), map_(std::move(reused)) {
    map_.reset();
}

void Submap::insert(const Keyframe& kf, const mrpt::poses::CPose2D& robotInSubmap) {
    keyframes_.push_back(kf.id);
    map_.insertSurface(kf.surface, robotInSubmap + kf.sensorOnRobot);
}

void Submap::clear() {
    keyframes_.clear();
    map_.clear();
}

matching::LineMap Submap::finish() {
    matching::LineMap map = std::move(map_);
    map_ = matching::LineMap(map.options());
    finished_ = true;
    return map;
}

}  // namespace toposlam::mapping
