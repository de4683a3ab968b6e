#pragma once
// One laser scan as the matcher reads it: per beam its bearing, range, validity and Cartesian
// point, all in the SENSOR frame (x forward, y left; metres, radians). Bearings are evenly
// spaced: beam i points at firstBearing() + i * bearingStep(); the step is negative when
// CObservation2DRangeScan::rightToLeft is false (clockwise sweep). Looking a bearing up
// (beamAt) is O(1): what the alignment scorer needs to test a pose against the reference
// scan without a search structure.
#include <mrpt/math/TPoint2D.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mrpt::obs {
class CObservation2DRangeScan;
}

namespace toposlam::matching {

class PolarScan {
  public:
    /// Copies the scan's geometry and valid readings; reuses this object's storage.
    void assign(const mrpt::obs::CObservation2DRangeScan& scan);
    /// Same from raw arrays: `ranges` (m) and `valid` per beam, evenly spaced bearings
    /// (rad). Readings that are invalid, non-finite, <= 0 or >= maxRange are not valid.
    void assign(double firstBearing, double bearingStep, const std::vector<float>& ranges,
                const std::vector<char>& valid, double maxRange);

    std::size_t size() const { return range_.size(); }
    bool empty() const { return range_.empty(); }
    bool valid(std::size_t beam) const { return valid_[beam] != 0; }
    double range(std::size_t beam) const { return range_[beam]; }
    double bearing(std::size_t beam) const;
    const mrpt::math::TPoint2D& point(std::size_t beam) const { return point_[beam]; }
    std::size_t validCount() const { return validCount_; }
    double maxRange() const { return maxRange_; }
    double firstBearing() const { return firstBearing_; }
    double bearingStep() const { return bearingStep_; }
    /// True when the beams cover the whole circle (index arithmetic wraps around).
    bool fullCircle() const { return fullCircle_; }

    /// Beam whose bearing is nearest to `bearing` (rad, any value), or -1 when `bearing`
    /// lies outside the field of view (more than half a step beyond the first/last beam).
    long beamAt(double bearing) const;
    /// Beam whose bearing is nearest to the direction of the point (x, y) (sensor frame, m),
    /// or -1 outside the field of view. Uses a fast arctangent (error < 1e-5 rad, far below
    /// any beam step): this lookup runs for every point of every ICP iteration.
    long beamAtPoint(double x, double y) const;
    /// Index `beam + offset`, wrapped on full-circle scans; -1 when out of range otherwise.
    long neighbour(long beam, long offset) const {  // inline: runs in every ICP inner loop
        const long n = static_cast<long>(range_.size());
        const long b = beam + offset;
        if (b >= 0 && b < n)
            return b;
        if (!fullCircle_)
            return -1;
        return b < 0 ? b + n : b - n;  // offsets are never more than one turn
    }

  private:
    void finish();

    std::vector<float> range_;
    std::vector<char> valid_;
    std::vector<mrpt::math::TPoint2D> point_;
    double firstBearing_ = 0, bearingStep_ = 0, maxRange_ = 0;
    bool fullCircle_ = false;
    std::size_t validCount_ = 0;
};

}  // namespace toposlam::matching
