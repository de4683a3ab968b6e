#include <toposlam/evaluation/FrameOffsetFit.h>

#include <cmath>

namespace toposlam::evaluation {

namespace {

// Mean translational error of the matched relations with every pose moved `d` m ahead.
double meanErrorAt(double d, const io::Trajectory2D& estimate, const PoseRelations& relations,
                   const RelativePoseErrorResult& scored) {
    const auto ahead = [d](const mrpt::math::TPose2D& p) {
        return mrpt::math::TPose2D(p.x + d * std::cos(p.phi), p.y + d * std::sin(p.phi), p.phi);
    };
    double sum = 0;
    for (const RelationError& e : scored.errors) {
        const mrpt::math::TPose2D err =
            relativePoseError(ahead(estimate[e.fromPose].pose), ahead(estimate[e.toPose].pose),
                              relations[e.relation].motion);
        sum += std::hypot(err.x, err.y);
    }
    return sum / static_cast<double>(scored.errors.size());
}

}  // namespace

FrameOffsetFit fitFrameOffset(const io::Trajectory2D& estimate, const PoseRelations& relations,
                              const RelativePoseErrorResult& scored, double maxOffset) {
    FrameOffsetFit fit;
    if (scored.errors.empty())
        return fit;
    const auto f = [&](double d) { return meanErrorAt(d, estimate, relations, scored); };
    fit.meanErrorAsIs = f(0);
    fit.meanError = fit.meanErrorAsIs;
    const double step = 0.01;
    const int steps = static_cast<int>(std::round(maxOffset / step));
    for (int k = -steps; k <= steps; ++k) {
        const double value = f(k * step);
        if (value < fit.meanError) {
            fit.meanError = value;
            fit.offset = k * step;
        }
    }
    // Golden section within the best step's neighbours.
    const double ratio = 0.5 * (std::sqrt(5.0) - 1);
    double a = fit.offset - step, b = fit.offset + step;
    double c = b - ratio * (b - a), d = a + ratio * (b - a);
    double fc = f(c), fd = f(d);
    while (b - a > 1e-4) {
        if (fc < fd) {
            b = d, d = c, fd = fc;
            c = b - ratio * (b - a), fc = f(c);
        } else {
            a = c, c = d, fc = fd;
            d = a + ratio * (b - a), fd = f(d);
        }
    }
    const double best = 0.5 * (a + b), value = f(best);
    if (value < fit.meanError) {
        fit.meanError = value;
        fit.offset = best;
    }
    return fit;
}

}  // namespace toposlam::evaluation
