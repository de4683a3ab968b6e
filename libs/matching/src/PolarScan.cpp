#include <mrpt/obs/CObservation2DRangeScan.h>
#include <toposlam/matching/PolarScan.h>

#include <cmath>

namespace toposlam::matching {

void PolarScan::assign(const mrpt::obs::CObservation2DRangeScan& scan) {
    const std::size_t n = scan.getScanSize();
    range_.resize(n);
    valid_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        range_[i] = scan.getScanRange(i);
        valid_[i] = scan.getScanRangeValidity(i) ? 1 : 0;
    }
    maxRange_ = scan.maxRange;
    firstBearing_ = n > 0 ? scan.getScanAngle(0) : 0.0;
    // From the aperture in double precision (getScanAngle works in float).
    bearingStep_ = n > 1 ? scan.aperture / static_cast<double>(n - 1) : 0.0;
    if (!scan.rightToLeft)
        bearingStep_ = -bearingStep_;
    finish();
}

void PolarScan::assign(double firstBearing, double bearingStep, const std::vector<float>& ranges,
                       const std::vector<char>& valid, double maxRange) {
    range_ = ranges;
    valid_ = valid;
    valid_.resize(range_.size(), 0);
    firstBearing_ = firstBearing;
    bearingStep_ = bearingStep;
    maxRange_ = maxRange;
    finish();
}

void PolarScan::finish() {
    const std::size_t n = range_.size();
    point_.resize(n);
    validCount_ = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double r = range_[i];
        if (!std::isfinite(r) || r <= 0 || r >= maxRange_)
            valid_[i] = 0;
        const double a = bearing(i);
        point_[i] = {r * std::cos(a), r * std::sin(a)};
        if (valid_[i])
            ++validCount_;
    }
    // Full circle when one more step after the last beam comes back to the first one.
    fullCircle_ = n > 2 && std::abs(std::abs(bearingStep_) * static_cast<double>(n) - 2 * M_PI) <
                               0.5 * std::abs(bearingStep_);
}

double PolarScan::bearing(std::size_t beam) const {
    return firstBearing_ + bearingStep_ * static_cast<double>(beam);
}

long PolarScan::beamAt(double bearing) const {
    const long n = static_cast<long>(range_.size());
    if (n == 0 || bearingStep_ == 0)
        return -1;
    double rel = (bearing - firstBearing_) / bearingStep_;  // in beam steps
    if (fullCircle_) {
        const double turn = 2 * M_PI / std::abs(bearingStep_);
        rel = std::fmod(rel, turn);
        if (rel < 0)
            rel += turn;
        long b = std::lround(rel);
        return b >= n ? b - n : b;
    }
    // Angles are periodic: bring `rel` into [-0.5, n-0.5] when some turn does.
    const double turn = 2 * M_PI / std::abs(bearingStep_);
    rel = std::fmod(rel + 0.5, turn);
    if (rel < 0)
        rel += turn;
    rel -= 0.5;
    if (rel > static_cast<double>(n) - 0.5)
        return -1;
    return std::lround(rel);
}

long PolarScan::neighbour(long beam, long offset) const {
    const long n = static_cast<long>(range_.size());
    long b = beam + offset;
    if (fullCircle_) {
        b %= n;
        return b < 0 ? b + n : b;
    }
    return (b < 0 || b >= n) ? -1 : b;
}

}  // namespace toposlam::matching
