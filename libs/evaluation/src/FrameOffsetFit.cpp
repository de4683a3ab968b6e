#include <toposlam/evaluation/FrameOffsetFit.h>

#include <cmath>

namespace toposlam::evaluation {

namespace {

// Mean translational error of the matched relations with every pose moved `d` m ahead.
double meanErrorAt(double d, const io::Trajectory2D& estimate, const PoseRelations& relations,
                   const RelativePoseErrorResult& scored) {
    double sum = 0;
    for (const RelationError& e : scored.errors) {
        const mrpt::math::TPose2D err =
            relativePoseError(poseAhead(estimate[e.fromPose].pose, d),
                              poseAhead(estimate[e.toPose].pose, d), relations[e.relation].motion);
        sum += std::hypot(err.x, err.y);
    }
    return sum / static_cast<double>(scored.errors.size());
}

}  // namespace

mrpt::math::TPose2D poseAhead(const mrpt::math::TPose2D& pose, double d) {
    return {pose.x + d * std::cos(pose.phi), pose.y + d * std::sin(pose.phi), pose.phi};
}

FrameOffsetFit fitFrameOffset(const io::Trajectory2D& estimate, const PoseRelations& relations,
                              const RelativePoseErrorResult& scored, double maxOffset) {
    FrameOffsetFit fit;
    if (scored.errors.empty())
        return fit;
    fit.meanErrorAsIs = meanErrorAt(0, estimate, relations, scored);
    fit.meanError = fit.meanErrorAsIs;
    // Every `step` within `half` of `centre`, the lowest kept.
    const auto scan = [&](double centre, double half, double step) {
        const int steps = static_cast<int>(std::round(half / step));
        for (int k = -steps; k <= steps; ++k) {
            const double d = centre + k * step;
            const double value = meanErrorAt(d, estimate, relations, scored);
            if (value < fit.meanError) {
                fit.meanError = value;
                fit.offset = d;
            }
        }
    };
    scan(0, maxOffset, 0.01);      // 1 cm steps over the whole range
    scan(fit.offset, 0.01, 1e-4);  // 0.1 mm steps around the best of them
    return fit;
}

}  // namespace toposlam::evaluation
