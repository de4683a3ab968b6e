#include <toposlam/mapping/Submap.h>

#include <algorithm>
#include <limits>
#include <utility>

namespace toposlam::mapping {

Submap::Submap(std::size_t anchor, const matching::LineMapOptions& options)
    : anchor_(anchor), map_(options) {}

Submap::Submap(std::size_t anchor, matching::LineMap&& reused)
    : anchor_(anchor), map_(std::move(reused)) {
    map_.reset();
}

void Submap::insert(const Keyframe& kf, const mrpt::poses::CPose2D& robotInSubmap) {
    const bool newPart = kf.placedByOdometry && !keyframes_.empty();
    keyframes_.push_back(kf.id);
    const std::size_t before = map_.size();
    const mrpt::poses::CPose2D sensor = robotInSubmap + kf.sensorOnRobot;
    map_.insertSurface(kf.surface, sensor);
    const double margin = map_.options().carveMargin;
    if (margin > 0 && kf.scan) {
        // Its new points that the keyframes before it saw through, then what it sees through.
        for (const auto& [scan, pose] : views_)
            map_.carve(scan, pose, before, margin);
        matching::PolarScan& scan = views_.emplace_back().first;
        scan.assign(*kf.scan);
        views_.back().second = sensor;
        map_.carve(scan, sensor, 0, margin);
    }
    if (newPart)
        parts_.push_back({kf.id, map_.scans()});
}

std::vector<std::size_t> Submap::partStarts() const {
    std::vector<std::size_t> starts{anchor_};
    for (const Part& p : parts_)
        starts.push_back(p.keyframe);
    return starts;
}

std::size_t Submap::partHolding(const matching::PolarScan& scan, const mrpt::poses::CPose2D& sensor,
                                double distance) const {
    if (parts_.empty())
        return anchor_;
    readingsPerPart_.assign(parts_.size() + 1, 0);
    matching::forEachReadingOnSurface(
        map_, scan, sensor, distance, [&](const matching::LineMapPoint& m) {
            const auto part = std::upper_bound(
                parts_.begin(), parts_.end(), m.firstScan,
                [](std::uint32_t first, const Part& q) { return first < q.firstScan; });
            ++readingsPerPart_[std::size_t(part - parts_.begin())];
        });
    // Ties go to the earlier part: the anchor keeps a scan that fits both equally.
    const std::size_t most =
        std::size_t(std::max_element(readingsPerPart_.begin(), readingsPerPart_.end()) -
                    readingsPerPart_.begin());
    return most == 0 ? anchor_ : parts_[most - 1].keyframe;
}

std::size_t Submap::readingsBeforeNewestPart(const matching::PolarScan& scan,
                                             const mrpt::poses::CPose2D& sensor,
                                             double distance) const {
    const std::uint32_t newest =
        parts_.empty() ? std::numeric_limits<std::uint32_t>::max() : parts_.back().firstScan;
    std::size_t on = 0;
    matching::forEachReadingOnSurface(
        map_, scan, sensor, distance,
        [&](const matching::LineMapPoint& m) { on += m.firstScan < newest ? 1 : 0; });
    return on;
}

void Submap::clear() {
    keyframes_.clear();
    views_.clear();
    parts_.clear();
    map_.clear();
}

matching::LineMap Submap::finish() {
    matching::LineMap map = std::move(map_);
    map_ = matching::LineMap(map.options());
    views_ = {};  // nothing is inserted any more
    finished_ = true;
    return map;
}

}  // namespace toposlam::mapping
