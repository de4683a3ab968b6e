#include <toposlam/features/JumpDetector.h>

#include <algorithm>
#include <cmath>
#include <ostream>

namespace toposlam::features {

void JumpDetectorOptions::declare(config::OptionsSchema& s) {
    s.flag("enabled", enabled, "cut runs at range jumps (graph paper eq. 1)");
    s.real("k", k, "", "jump when the gap to the next reading > k * step * range (paper: 15)")
        .above(0);
    s.real("noise_sigmas", noiseSigmas, "", "... and > this * sqrt(2) * range noise").atLeast(0);
}

bool JumpDetector::isJump(const ScanPoints& pts, std::size_t k, double sigma) const {
    const double dx = pts.x(k + 1) - pts.x(k), dy = pts.y(k + 1) - pts.y(k);
    const double gap2 = dx * dx + dy * dy;
    const double byRange = options.k * pts.angularStep() * std::min(pts.range(k), pts.range(k + 1));
    const double byNoise = options.noiseSigmas * M_SQRT2 * sigma;
    const double threshold = std::max(byRange, byNoise);
    return gap2 > threshold * threshold;
}

void JumpDetector::findRuns(const ScanPoints& pts, double sigma,
                            std::vector<PointRun>& runs) const {
    runs.clear();
    const std::size_t n = pts.size();
    const double* __restrict x = pts.xData();
    const double* __restrict y = pts.yData();
    const double* __restrict r = pts.rangeData();  // 0 where invalid
    const double perRange = options.k * pts.angularStep();
    const double byNoise = options.noiseSigmas * M_SQRT2 * sigma;
    const bool enabled = options.enabled;
    std::size_t k = 0;
    EndpointType nextBeginType = EndpointType::Open;
    while (k < n) {
        if (!(r[k] > 0)) {
            ++k;
            nextBeginType = EndpointType::Open;
            continue;
        }
        PointRun run;
        run.begin = static_cast<std::uint32_t>(k);
        run.beginType = nextBeginType;
        nextBeginType = EndpointType::Open;
        for (; k + 1 < n && r[k + 1] > 0; ++k) {
            if (!enabled)
                continue;
            // Same test as isJump(), inlined.
            const double dx = x[k + 1] - x[k], dy = y[k + 1] - y[k];
            const double t = std::max(perRange * std::min(r[k], r[k + 1]), byNoise);
            if (dx * dx + dy * dy > t * t) {
                // The nearer side occludes the farther one.
                const bool thisNearer = r[k] < r[k + 1];
                run.endType = thisNearer ? EndpointType::Jump : EndpointType::Open;
                nextBeginType = thisNearer ? EndpointType::Open : EndpointType::Jump;
                break;
            }
        }
        run.end = static_cast<std::uint32_t>(k);
        runs.push_back(run);
        ++k;
    }
}

}  // namespace toposlam::features
