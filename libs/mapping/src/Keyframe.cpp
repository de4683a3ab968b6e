#include <toposlam/mapping/Keyframe.h>

#include <algorithm>
#include <cmath>

namespace toposlam::mapping {

ScanSignature scanSignature(const matching::PolarScan& scan) {
    ScanSignature s{};
    constexpr double kBand = 0.5;  // m
    std::size_t n = 0;
    for (std::size_t b = 0; b < scan.size(); ++b) {
        if (!scan.valid(b))
            continue;
        const std::size_t band = std::min(s.size() - 1, std::size_t(scan.range(b) / kBand));
        s[band] += 1;
        ++n;
    }
    if (n > 0)
        for (float& v : s)
            v /= float(n);
    return s;
}

double signatureDistance(const ScanSignature& a, const ScanSignature& b) {
    double d = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        d += std::abs(a[i] - b[i]);
    return d;
}

}  // namespace toposlam::mapping
