#include <toposlam/features/ScanPoints.h>

#include <algorithm>
#include <cmath>

namespace toposlam::features {

void ScanPoints::updateGeometry(std::size_t n, float aperture, bool rightToLeft) {
    reversed_ = !rightToLeft;
    if (n == geomSize_ && aperture == geomAperture_)
        return;
    geomSize_ = n;
    geomAperture_ = aperture;
    geomCos_.resize(n);
    geomSin_.resize(n);
    // MRPT: beam i of a right-to-left scan points at -aperture/2 + i*aperture/(n-1); a
    // left-to-right scan mirrors it. Canonical order is always the right-to-left one.
    step_ = n > 1 ? static_cast<double>(aperture) / static_cast<double>(n - 1) : 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double a = -0.5 * static_cast<double>(aperture) + static_cast<double>(k) * step_;
        geomCos_[k] = std::cos(a);
        geomSin_[k] = std::sin(a);
    }
}

void ScanPoints::assign(const mrpt::obs::CObservation2DRangeScan& scan, double minValidRange) {
    const std::size_t n = scan.getScanSize();
    updateGeometry(n, scan.aperture, scan.rightToLeft);
    range_.resize(n);
    x_.resize(n);
    y_.resize(n);
    valid_.resize(n);
    cos_ = geomCos_.data();
    sin_ = geomSin_.data();
    seam_ = 0;
    cyclic_ = false;
    validCount_ = 0;
    if (n == 0)
        return;

    const float* ranges = &scan.getScanRange(0);  // contiguous storage
    const double maxRange = scan.maxRange > 0 ? scan.maxRange : HUGE_VAL;
    const double minRange = std::max(0.0, minValidRange);
    double* __restrict range = range_.data();
    std::uint8_t* __restrict valid = valid_.data();
    std::size_t count = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = reversed_ ? n - 1 - k : k;
        const double r = ranges[i];
        // The comparisons are false for NaN, so NaN readings are invalid too. The (out of
        // line) validity flag is asked only about plausible readings.
        const bool ok = r > minRange && r < maxRange && scan.getScanRangeValidity(i);
        valid[k] = ok;
        count += ok;
        range[k] = ok ? r : 0.0;
    }
    validCount_ = count;

    // A full circle: the gap from the last beam round to the first is one step.
    cyclic_ =
        n >= 3 && std::abs(2 * M_PI - (static_cast<double>(scan.aperture) + step_)) < 0.5 * step_;
    if (cyclic_)
        chooseSeam();
    if (seam_ != 0) {
        std::rotate(range_.begin(), range_.begin() + static_cast<std::ptrdiff_t>(seam_),
                    range_.end());
        std::rotate(valid_.begin(), valid_.begin() + static_cast<std::ptrdiff_t>(seam_),
                    valid_.end());
    }
    if (seam_ != 0) {
        rotatedCos_.resize(n);
        rotatedSin_.resize(n);
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t g = k + seam_ < n ? k + seam_ : k + seam_ - n;
            rotatedCos_[k] = geomCos_[g];
            rotatedSin_[k] = geomSin_[g];
        }
        cos_ = rotatedCos_.data();
        sin_ = rotatedSin_.data();
    }
    double* __restrict x = x_.data();
    double* __restrict y = y_.data();
    const double* __restrict r = range_.data();
    for (std::size_t k = 0; k < n; ++k) {
        x[k] = r[k] * cos_[k];
        y[k] = r[k] * sin_[k];
    }
}

void ScanPoints::chooseSeam() {
    const std::size_t n = range_.size();
    const auto next = [n](std::size_t k) { return k + 1 < n ? k + 1 : 0; };
    // 1. Right after an invalid reading.
    for (std::size_t k = 0; k < n; ++k) {
        if (!valid_[k]) {
            seam_ = next(k);
            return;
        }
    }
    // 2. At the largest range discontinuity, if it is a jump by the graph paper's eq. (1)
    //    (gap > 15 * step * range). Consecutive points at ranges a, b are |a - b| apart along
    //    the beams, which is the dominant part of their distance at a jump.
    double bestGap = 0;
    std::size_t bestK = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const double a = range_[k], b = range_[next(k)];
        const double gap = std::abs(a - b) / (std::min(a, b) * step_);
        if (gap > bestGap) {
            bestGap = gap;
            bestK = k;
        }
    }
    if (bestGap > 15.0) {
        seam_ = next(bestK);
        return;
    }
    // 3. At the flattest reading: k lies on the line through its neighbours exactly when
    //    r(k) (1/r(k-1) + 1/r(k+1)) = 2 cos(step) (the exact slope difference, SlopeDifference.h).
    const double c = std::cos(step_);
    double bestFlat = HUGE_VAL;
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t prev = k == 0 ? n - 1 : k - 1;
        const double flat = std::abs(range_[k] * (1 / range_[prev] + 1 / range_[next(k)]) - 2 * c);
        if (flat < bestFlat) {
            bestFlat = flat;
            seam_ = k;
        }
    }
}

void ScanPoints::copyFrom(const ScanPoints& o) {
    if (this == &o)
        return;
    range_ = o.range_;
    x_ = o.x_;
    y_ = o.y_;
    valid_ = o.valid_;
    if (geomSize_ != o.geomSize_ || geomAperture_ != o.geomAperture_) {
        geomCos_ = o.geomCos_;
        geomSin_ = o.geomSin_;
        geomSize_ = o.geomSize_;
        geomAperture_ = o.geomAperture_;
    }
    step_ = o.step_;
    reversed_ = o.reversed_;
    cyclic_ = o.cyclic_;
    seam_ = o.seam_;
    validCount_ = o.validCount_;
    if (o.cos_ == o.geomCos_.data()) {
        cos_ = geomCos_.data();
        sin_ = geomSin_.data();
    } else {
        rotatedCos_ = o.rotatedCos_;
        rotatedSin_ = o.rotatedSin_;
        cos_ = rotatedCos_.data();
        sin_ = rotatedSin_.data();
    }
}

void ScanPoints::toScanOrder(ScanFeatures& f) {
    // Segments: beam indices, and their orientation when the scan runs clockwise.
    bool sorted = true;
    for (std::size_t i = 0; i < f.segments.size(); ++i) {
        LineSegment& s = f.segments[i];
        s.firstBeam = beam(s.firstBeam);
        s.lastBeam = beam(s.lastBeam);
        if (reversed_) {
            std::swap(s.firstBeam, s.lastBeam);
            std::swap(s.start, s.end);
            std::swap(s.startType, s.endType);
        }
        if (i > 0 && f.segments[i - 1].firstBeam > s.firstBeam)
            sorted = false;
    }
    if (!sorted) {
        const std::size_t m = f.segments.size();
        order_.resize(m);
        newIndex_.resize(m);
        for (std::size_t i = 0; i < m; ++i)
            order_[i] = static_cast<std::uint32_t>(i);
        // std::sort, unlike stable_sort, never allocates; ties are broken explicitly.
        std::sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) {
            const LineSegment &sa = f.segments[a], &sb = f.segments[b];
            if (sa.firstBeam != sb.firstBeam)
                return sa.firstBeam < sb.firstBeam;
            if (sa.lastBeam != sb.lastBeam)
                return sa.lastBeam < sb.lastBeam;
            return a < b;
        });
        segmentsTmp_ = f.segments;
        for (std::size_t i = 0; i < m; ++i) {
            newIndex_[order_[i]] = static_cast<std::uint32_t>(i);
            f.segments[i] = segmentsTmp_[order_[i]];
        }
        for (Corner& c : f.corners) {
            c.segmentBefore = newIndex_[c.segmentBefore];
            c.segmentAfter = newIndex_[c.segmentAfter];
        }
    }
    for (Corner& c : f.corners) {
        c.beam = beam(c.beam);
        if (f.segments[c.segmentBefore].firstBeam > f.segments[c.segmentAfter].firstBeam) {
            std::swap(c.segmentBefore, c.segmentAfter);
        }
    }
    for (Endpoint& e : f.endpoints)
        e.beam = beam(e.beam);
    if (reversed_) {
        std::reverse(f.corners.begin(), f.corners.end());
        std::reverse(f.endpoints.begin(), f.endpoints.end());
    }
    if (seam_ != 0) {
        std::sort(f.corners.begin(), f.corners.end(),
                  [](const Corner& a, const Corner& b) { return a.beam < b.beam; });
        std::sort(f.endpoints.begin(), f.endpoints.end(),
                  [](const Endpoint& a, const Endpoint& b) { return a.beam < b.beam; });
    }
}

}  // namespace toposlam::features
