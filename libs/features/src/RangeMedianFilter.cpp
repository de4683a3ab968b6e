#include <toposlam/features/RangeMedianFilter.h>

#include <algorithm>
#include <array>
#include <stdexcept>

namespace toposlam::features {

void RangeMedianFilter::apply(ScanPoints& pts) {
    if (window % 2 == 0 || window > 15) {
        throw std::invalid_argument("RangeMedianFilter: window must be odd and at most 15");
    }
    if (window <= 1)
        return;
    const std::size_t n = pts.size(), half = window / 2;
    original_.resize(n);
    for (std::size_t k = 0; k < n; ++k)
        original_[k] = pts.range(k);

    if (window == 3) {  // the usual case, without sorting
        for (std::size_t k = 1; k + 1 < n; ++k) {
            if (!pts.valid(k) || !pts.valid(k - 1) || !pts.valid(k + 1))
                continue;
            const double a = original_[k - 1], b = original_[k], c = original_[k + 1];
            pts.setRange(k, std::max(std::min(a, b), std::min(std::max(a, b), c)));
        }
        return;
    }
    std::array<double, 15> buf{};
    for (std::size_t k = 0; k < n; ++k) {
        if (!pts.valid(k))
            continue;
        std::size_t lo = k, hi = k;
        while (lo > 0 && k - lo < half && pts.valid(lo - 1))
            --lo;
        while (hi + 1 < n && hi - k < half && pts.valid(hi + 1))
            ++hi;
        // Keep the window centred on k: use the same reach on both sides.
        const std::size_t reach = std::min(k - lo, hi - k);
        const std::size_t m = 2 * reach + 1;
        if (m < 3)
            continue;
        std::copy(original_.begin() + static_cast<std::ptrdiff_t>(k - reach),
                  original_.begin() + static_cast<std::ptrdiff_t>(k + reach + 1), buf.begin());
        std::nth_element(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(reach),
                         buf.begin() + static_cast<std::ptrdiff_t>(m));
        pts.setRange(k, buf[reach]);
    }
}

}  // namespace toposlam::features
