#include <toposlam/features/SlopeDifference.h>

#include <algorithm>
#include <cmath>

namespace toposlam::features {

void SlopeDifference::compute(const ScanPoints& pts, const std::vector<PointRun>& runs,
                              bool paperForm, double cornerThreshold, double sigma, double z,
                              unsigned minBaseline) {
    const std::size_t n = pts.size();
    dk.assign(n, 0.0);
    baseline.assign(n, 0);
    threshold.assign(n, cornerThreshold);
    const double step = pts.angularStep();
    if (!(step > 0))
        return;

    if (paperForm) {
        for (const PointRun& run : runs) {
            for (std::size_t i = run.begin + 1; i < run.end; ++i) {
                dk[i] =
                    slopeDifferencePaper(pts.range(i - 1), pts.range(i), pts.range(i + 1), step);
                baseline[i] = 1;
            }
        }
        return;
    }

    // Noise of dk_s: sqrt(6) sigma / chord. The chord that keeps z * noise at the threshold:
    const double noiseNumerator = z * std::sqrt(6.0) * sigma;
    const double chord = noiseChord(sigma, z, cornerThreshold);
    if (tableStep_ != step) {
        tableStep_ = step;
        cosTable_.clear();
        sinTable_.clear();
        const std::size_t maxBaseline = static_cast<std::size_t>(3.0 / step) + 2;
        cosTable_.reserve(maxBaseline);
        sinTable_.reserve(maxBaseline);
    }
    for (const PointRun& run : runs) {
        for (std::size_t i = run.begin + 1; i < run.end; ++i) {
            const double r = pts.range(i);
            const double wanted =
                std::max(static_cast<double>(minBaseline), std::ceil(chord / (r * step)));
            const std::size_t room = std::min(i - run.begin, run.end - i);
            const std::size_t s = std::max<std::size_t>(
                1, std::min<std::size_t>(room, static_cast<std::size_t>(std::min(wanted, 1e6))));
            // Angles beyond ~170 deg make no sense as a baseline (and sin -> 0).
            if (static_cast<double>(s) * step > 3.0)
                continue;
            while (cosTable_.size() <= s) {
                const double a = static_cast<double>(cosTable_.size()) * step;
                cosTable_.push_back(std::cos(a));
                sinTable_.push_back(std::sin(a));
            }
            dk[i] = slopeDifferenceExact(pts.range(i - s), r, pts.range(i + s), cosTable_[s],
                                         sinTable_[s]);
            baseline[i] = static_cast<std::uint32_t>(s);
            // Clipped near a run end: less of the corner's dk is on one reading and the noise is
            // larger; raise the threshold for the noise only (sigma = 0: no raise).
            const double noise = noiseNumerator / (r * static_cast<double>(s) * step);
            threshold[i] = std::max(cornerThreshold, noise);
        }
    }
}

}  // namespace toposlam::features
