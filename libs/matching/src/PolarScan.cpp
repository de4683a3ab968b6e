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
    // In beam steps from the first beam, brought into [-0.5, turn - 0.5): angles are periodic.
    const double turn = 2 * M_PI / std::abs(bearingStep_);
    double rel = (bearing - firstBearing_) / bearingStep_;
    if (std::abs(rel) > 2 * turn)
        rel = std::fmod(rel, turn);  // far outside: rare, so the slow path is fine
    while (rel < -0.5)
        rel += turn;
    while (rel >= turn - 0.5)
        rel -= turn;
    const long b = std::lround(rel);
    if (fullCircle_)
        return b >= n ? b - n : (b < 0 ? b + n : b);
    return rel > static_cast<double>(n) - 0.5 ? -1 : b;
}

namespace {
/// atan2 with a max error of ~1e-5 rad: octant reduction and a minimax polynomial for atan
/// on [0, 1].
double fastAtan2(double y, double x) {
    const double ax = std::abs(x), ay = std::abs(y);
    const double hi = std::max(ax, ay), lo = std::min(ax, ay);
    if (hi == 0)
        return 0.0;
    const double t = lo / hi, t2 = t * t;
    double a =
        t * (0.99997726 +
             t2 * (-0.33262347 +
                   t2 * (0.19354346 + t2 * (-0.11643287 + t2 * (0.05265332 + t2 * -0.01172120)))));
    if (ay > ax)
        a = M_PI_2 - a;
    if (x < 0)
        a = M_PI - a;
    return y < 0 ? -a : a;
}
}  // namespace

long PolarScan::beamAtPoint(double x, double y) const {
    return beamAt(fastAtan2(y, x));
}

}  // namespace toposlam::matching
