#include <toposlam/mapping/MapRange.h>

#include <algorithm>
#include <cstddef>

namespace toposlam::mapping {

double mapRange(const matching::PolarScan& scan, const GraphSlamOptions& options) {
    std::size_t far = 0;
    for (std::size_t b = 0; b < scan.size(); ++b)
        far += scan.valid(b) && scan.range(b) > options.mapMaxRange;
    const bool openSpace =
        double(far) > options.mapFarShare * double(std::max<std::size_t>(1, scan.validCount()));
    return openSpace ? std::max(options.mapMaxRange, scan.maxRange()) : options.mapMaxRange;
}

}  // namespace toposlam::mapping
