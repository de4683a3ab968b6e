#include <toposlam/features/SlopeDifference.h>

#include <algorithm>
#include <cmath>

namespace toposlam::features {

void SlopeDifference::compute(const ScanPoints& pts, const std::vector<PointRun>& runs,
                              bool paperForm, double cornerThreshold, double sigma, double z,
                              unsigned minBaseline) {
    const std::size_t n = pts.size();
    // Only baseline needs clearing (0 = not evaluated); the rest is read where it is not.
    numerator.resize(n);
    scale.resize(n);
    threshold.resize(n);
    baseline.assign(n, 0);
    above.clear();
    paper_ = paperForm;
    cornerThreshold_ = cornerThreshold;
    const double step = pts.angularStep();
    if (!(step > 0))
        return;

    if (paperForm) {
        computePaperForm(pts, runs, step);
        return;
    }

    // Exact form over a baseline of s readings, each of the three readings replaced by the
    // mean inverse range of the 2m+1 readings around it (m = s/2; m = 0 without noise). On a
    // straight line 1/r is a sinusoid of the bearing, so a symmetric mean scales all three by
    // the same factor and dk stays exactly 0; noise drops by sqrt(2m+1):
    //     std(dk) = sqrt(6) sigma / (r dtheta * s sqrt(2m+1)) = sqrt(6) sigma / (r dtheta gain(s)).
    maxBaseline_ = static_cast<std::size_t>(3.0 / step) + 2;  // 3 rad at most
    smooth_ = sigma > 0;
    updateTables(step);
    computeRunningSums(pts);
    double* __restrict prefix = prefix_.data();
    double* __restrict inverse = inverse_.data();
    // z * noise of dk_s = noiseScale / (r gain(s)): a baseline is enough when that is below
    // the threshold.
    noiseScale_ = z * std::sqrt(6.0) * sigma / step;
    sMin_ = std::max<std::size_t>(1, minBaseline);
    const double* __restrict invGain = invGain_.data();
    double* __restrict numeratorOut = numerator.data();
    double* __restrict scaleOut = scale.data();
    double* __restrict thresholdOut = threshold.data();  // set where above: see the header
    std::uint32_t* __restrict baselineOut = baseline.data();
    // Blocks of readings share one baseline, the one the block's nearest reading needs (the
    // noise grows with 1/r): the inner loop is then a fixed stencil on the running sums.
    // Readings too close to a run end for it are done one by one (evaluateAt), with the
    // baseline clipped.
    constexpr std::size_t kBlock = 16;
    std::size_t s = sMin_;  // carried from block to block: ranges change slowly
    for (const PointRun& run : runs) {
        for (std::size_t b = run.begin + 1; b < run.end; b += kBlock) {
            const std::size_t e = std::min<std::size_t>(b + kBlock, run.end);  // exclusive
            // The nearest reading sets the noise; a run has no jumps, so it is one of the block's
            // ends or, at a convex bend, near its middle.
            const double maxInverse =
                std::max({inverse[b], inverse[(b + e - 1) / 2], inverse[e - 1]});
            const double noiseBlock = noiseScale_ * maxInverse;
            while (s < maxBaseline_ && invGain[s] * noiseBlock > cornerThreshold)
                ++s;
            while (s > sMin_ && invGain[s - 1] * noiseBlock <= cornerThreshold)
                --s;
            const std::size_t m = smooth_ ? s / 2 : 0, reach = s + m;
            const std::size_t lo = std::max(b, run.begin + reach);
            const std::size_t hi = std::min(e, run.end + 1 > reach ? run.end + 1 - reach : 0);
            for (std::size_t i = b; i < std::min(lo, e); ++i) {
                evaluateAt(i, run.begin, run.end, s, noiseScale_ * (prefix[i + 1] - prefix[i]));
            }
            const double c2 = 2 * cosTable_[s], invSin = invSinTable_[s];
            const double noiseGain = noiseScale_ * invGain[s];
            if (lo < hi) {
                // Offsets from lo, so that every access is a plain unit-stride stream.
                const std::size_t count = hi - lo;
                const double* __restrict centreHi = prefix + lo + m + 1;
                const double* __restrict centreLo = prefix + lo - m;
                const double* __restrict beforeHi = prefix + lo - s + m + 1;
                const double* __restrict beforeLo = prefix + lo - s - m;
                const double* __restrict afterHi = prefix + lo + s + m + 1;
                const double* __restrict afterLo = prefix + lo + s - m;
                double* __restrict num = numeratorOut + lo;
                double* __restrict sc = scaleOut + lo;
                for (std::size_t j = 0; j < count; ++j) {
                    const double centre = centreHi[j] - centreLo[j];
                    const double v =
                        (beforeHi[j] - beforeLo[j] + afterHi[j] - afterLo[j] - c2 * centre) *
                        invSin;
                    num[j] = v;
                    sc[j] = centre;
                    if (std::abs(v) > cornerThreshold * centre) {  // rare: check the exact one
                        const double t = std::max(cornerThreshold, noiseGain * inverse[lo + j]);
                        thresholdOut[lo + j] = t;
                        if (std::abs(v) > t * centre) {
                            above.push_back(static_cast<std::uint32_t>(lo + j));
                        }
                    }
                }
                std::fill(baselineOut + lo, baselineOut + hi, static_cast<std::uint32_t>(s));
            }
            for (std::size_t i = std::max(hi, lo); i < e; ++i) {
                evaluateAt(i, run.begin, run.end, s, noiseScale_ * (prefix[i + 1] - prefix[i]));
            }
        }
    }
}

void SlopeDifference::computePaperForm(const ScanPoints& pts, const std::vector<PointRun>& runs,
                                       double step) {
    for (const PointRun& run : runs) {
        for (std::size_t i = run.begin + 1; i < run.end; ++i) {
            numerator[i] =
                slopeDifferencePaper(pts.range(i - 1), pts.range(i), pts.range(i + 1), step);
            scale[i] = 1;
            baseline[i] = 1;
            threshold[i] = cornerThreshold_;
        }
    }
}

void SlopeDifference::updateTables(double step) {
    if (tableStep_ == step && tableSmooth_ == smooth_)
        return;  // per scan geometry, not per scan
    tableStep_ = step;
    tableSmooth_ = smooth_;
    cosTable_.resize(maxBaseline_ + 1);
    invSinTable_.resize(maxBaseline_ + 1);
    invGain_.resize(maxBaseline_ + 1);
    for (std::size_t k = 0; k <= maxBaseline_; ++k) {
        const double a = static_cast<double>(k) * step;
        cosTable_[k] = std::cos(a);
        invSinTable_[k] = k > 0 ? 1 / std::sin(a) : 0;
        const double m = smooth_ ? static_cast<double>(k / 2) : 0.0;
        invGain_[k] = k > 0 ? 1 / (static_cast<double>(k) * std::sqrt(2 * m + 1)) : HUGE_VAL;
    }
}

void SlopeDifference::computeRunningSums(const ScanPoints& pts) {
    // Running sums of inverse ranges: a window mean costs two lookups. (The three windows have
    // the same size, so their sums can stand for their means in dk.)
    const std::size_t n = pts.size();
    prefix_.resize(n + 1);
    inverse_.resize(n);
    double* __restrict prefix = prefix_.data();
    double* __restrict inverse = inverse_.data();
    const double* __restrict range = pts.rangeData();  // 0 where invalid
    for (std::size_t k = 0; k < n; ++k)
        inverse[k] = range[k] > 0 ? 1.0 / range[k] : 0.0;
    prefix[0] = 0;
    for (std::size_t k = 0; k < n; ++k)
        prefix[k + 1] = prefix[k] + inverse[k];
}

bool SlopeDifference::evaluateAt(std::size_t i, std::size_t runBegin, std::size_t runEnd,
                                 std::size_t s, double noiseHere) {
    // Near a run end: the largest baseline whose windows still fit in the run
    // (u + u/2 <= room when smoothing, u <= room otherwise).
    const std::size_t room = std::min(i - runBegin, runEnd - i);
    std::size_t used = s;
    if (used + (smooth_ ? used / 2 : 0) > room) {
        used = smooth_ ? std::max(2 * (room / 3), room >= 1 ? 2 * ((room - 1) / 3) + 1 : 0) : room;
        if (used == 0)
            return false;
    }
    const std::size_t m = smooth_ ? used / 2 : 0;
    const double* prefix = prefix_.data();
    const auto windowSum = [prefix](std::size_t c, std::size_t w) {
        return prefix[c + w + 1] - prefix[c - w];
    };
    // dk = ((S- + S+) / Sc - 2 cos a) / sin a, kept as a fraction over Sc.
    const double centre = windowSum(i, m);
    numerator[i] =
        (windowSum(i - used, m) + windowSum(i + used, m) - 2 * cosTable_[used] * centre) *
        invSinTable_[used];
    scale[i] = centre;
    baseline[i] = static_cast<std::uint32_t>(used);
    // Clipped near a run end: the noise is larger; raise the threshold for it.
    threshold[i] = std::max(cornerThreshold_, noiseHere * invGain_[used]);
    if (std::abs(numerator[i]) > threshold[i] * centre)
        above.push_back(static_cast<std::uint32_t>(i));
    return true;
}

}  // namespace toposlam::features
