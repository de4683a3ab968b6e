#pragma once
// A 2D range scan as the extractors see it: readings in COUNTER-CLOCKWISE beam order (the
// "canonical" order, whatever the scan's rightToLeft flag), each with its range, its point in
// the sensor frame (x forward, y left, m) and whether it is a usable return. Extracting in one
// fixed order makes left-to-right and right-to-left scans of the same scene give the same
// features; toScanOrder() maps the result back to the scan's own beam indices.
//
// A reading is invalid when MRPT marks it so, when it is NaN or infinite, when it is <= 0 or
// <= minValidRange, or when it is >= the scan's maxRange (a "no return" reading).
//
// Full-circle scans (beams evenly spaced all around, first and last beam one step apart) are
// cut at a seam, so that no line or corner straddles the end of the array: just after an
// invalid reading if there is one, otherwise at the largest range discontinuity if it is a
// jump (graph paper eq. 1), otherwise at the flattest reading (mid-wall).
//
// The object is a reusable workspace: assign() reuses its buffers (no allocation once warmed up
// on scans of the same size) and caches the beam directions of the last scan geometry.
#include <mrpt/math/TPoint2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <toposlam/features/ScanFeatures.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace toposlam::features {

class ScanPoints {
  public:
    /// Loads a scan. `minValidRange` (m): readings at or below it are invalid too.
    void assign(const mrpt::obs::CObservation2DRangeScan& scan, double minValidRange = 0);

    /// Number of readings (valid or not).
    std::size_t size() const { return range_.size(); }
    /// Angle between consecutive beams (rad, > 0; 0 for scans of fewer than 2 beams).
    double angularStep() const { return step_; }
    /// True when the beams cover the full circle and the array was cut at a seam.
    bool cyclic() const { return cyclic_; }

    // Canonical index k = 0..size()-1, bearings increasing (counter-clockwise).
    bool valid(std::size_t k) const { return valid_[k] != 0; }
    double range(std::size_t k) const { return range_[k]; }  ///< m; 0 for invalid readings
    double x(std::size_t k) const { return x_[k]; }          ///< m, sensor frame
    double y(std::size_t k) const { return y_[k]; }          ///< m, sensor frame
    mrpt::math::TPoint2D point(std::size_t k) const { return {x_[k], y_[k]}; }
    double cosBearing(std::size_t k) const { return cos_[k]; }
    double sinBearing(std::size_t k) const { return sin_[k]; }
    /// Contiguous arrays (canonical order) for tight loops.
    const double* xData() const { return x_.data(); }
    const double* yData() const { return y_.data(); }
    const double* rangeData() const { return range_.data(); }
    /// The scan's own beam index of canonical reading k.
    std::uint32_t beam(std::size_t k) const {
        const std::size_t rotated = k + seam_ < size() ? k + seam_ : k + seam_ - size();
        return static_cast<std::uint32_t>(reversed_ ? size() - 1 - rotated : rotated);
    }
    std::size_t validCount() const { return validCount_; }

    /// Replaces the point of canonical reading k (used by filters that smooth ranges).
    void setRange(std::size_t k, double r) {
        range_[k] = r;
        x_[k] = r * cos_[k];
        y_[k] = r * sin_[k];
    }
    /// This becomes a copy of `other` (reusing this object's buffers).
    void copyFrom(const ScanPoints& other);

    /// Maps features extracted in canonical order (beam fields holding canonical indices,
    /// "before"/"start" meaning lower canonical index) to the scan's own beam indices and
    /// orderings as ScanFeatures documents them. Uses internal buffers (no allocation once
    /// warmed up).
    void toScanOrder(ScanFeatures& features);

  private:
    void updateGeometry(std::size_t n, float aperture, bool rightToLeft);
    void chooseSeam();

    std::vector<double> range_, x_, y_;
    const double *cos_ = nullptr, *sin_ = nullptr;  // geometry, rotated to the seam
    std::vector<double> rotatedCos_, rotatedSin_;   // used only when there is a seam
    std::vector<std::uint8_t> valid_;
    // Bearings of the cached geometry, in canonical (unrotated) order.
    std::vector<double> geomCos_, geomSin_;
    std::size_t geomSize_ = 0;
    float geomAperture_ = -1;
    double step_ = 0;
    bool reversed_ = false, cyclic_ = false;
    std::size_t seam_ = 0, validCount_ = 0;
    // toScanOrder() workspace.
    std::vector<std::uint32_t> order_, newIndex_;
    std::vector<LineSegment> segmentsTmp_;
};

}  // namespace toposlam::features
