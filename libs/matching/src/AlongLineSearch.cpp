#include <toposlam/matching/AlongLineSearch.h>

#include <cmath>

namespace toposlam::matching {

mrpt::poses::CPose2D searchAlongLine(const PolarScan& reference, const PolarScan& current,
                                     const mrpt::poses::CPose2D& pose,
                                     const mrpt::math::TPoint2D& direction,
                                     const AlongLineSearchOptions& options,
                                     const AlignmentScoreOptions& score) {
    AlignmentScoreOptions sparse = score;
    sparse.stride = options.stride;
    const auto value = [&](double s) {
        const mrpt::poses::CPose2D p(pose.x() + s * direction.x, pose.y() + s * direction.y,
                                     pose.phi());
        const AlignmentScore a = scoreAlignment(reference, current, p, sparse);
        return double(a.inliers) - double(a.violations);
    };
    double best = 0, bestValue = value(0.0);
    const long coarse = long(std::ceil(options.range / options.coarseStep));
    for (long k = -coarse; k <= coarse; ++k) {
        if (k == 0)
            continue;
        const double s = double(k) * options.coarseStep, v = value(s);
        // Ties go to the smaller offset: no move without evidence.
        if (v > bestValue || (v == bestValue && std::abs(s) < std::abs(best)))
            best = s, bestValue = v;
    }
    const double centre = best;
    const long fine = long(std::ceil(options.coarseStep / options.fineStep));
    for (long k = -fine; k <= fine; ++k) {
        if (k == 0)
            continue;
        const double s = centre + double(k) * options.fineStep, v = value(s);
        if (v > bestValue)
            best = s, bestValue = v;
    }
    return mrpt::poses::CPose2D(pose.x() + best * direction.x, pose.y() + best * direction.y,
                                pose.phi());
}

}  // namespace toposlam::matching
