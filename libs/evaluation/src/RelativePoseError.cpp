#include <mrpt/core/bits_math.h>
#include <toposlam/evaluation/RelativePoseError.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace toposlam::evaluation {

namespace {

bool isFinite(const mrpt::math::TPose2D& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.phi);
}

}  // namespace

mrpt::math::TPose2D relativePoseError(const mrpt::math::TPose2D& from,
                                      const mrpt::math::TPose2D& to,
                                      const mrpt::math::TPose2D& trueMotion) {
    // TPose2D's a - b is the MRPT ⊖: b⁻¹ ⊕ a (with phi wrapped).
    const mrpt::math::TPose2D estimatedMotion = to - from;  // from⁻¹ ⊕ to
    return estimatedMotion - trueMotion;                    // δ_gt⁻¹ ⊕ δ_est
}

RelativePoseErrorResult evaluateRelativePoseError(const io::Trajectory2D& estimate,
                                                  const PoseRelations& relations,
                                                  const RelativePoseErrorOptions& options) {
    for (std::size_t i = 0; i < estimate.size(); ++i) {
        if (!isFinite(estimate[i].pose) || !std::isfinite(estimate[i].stamp)) {
            throw std::invalid_argument("trajectory pose " + std::to_string(i) + " is not finite");
        }
    }
    const StampedPoseLookup lookup(estimate, options.stampTolerance);

    RelativePoseErrorResult result;
    result.totalRelations = relations.size();
    std::vector<double> translation, rotation, translationSquared, rotationSquared;
    for (std::size_t r = 0; r < relations.size(); ++r) {
        const auto from = lookup.find(relations[r].stamp1);
        const auto to = lookup.find(relations[r].stamp2);
        if (!from || !to)
            continue;

        RelationError e;
        e.relation = r;
        e.fromPose = *from;
        e.toPose = *to;
        e.error = relativePoseError(estimate[*from].pose, estimate[*to].pose, relations[r].motion);
        e.translation = std::hypot(e.error.x, e.error.y);
        e.rotationDeg = mrpt::RAD2DEG(std::abs(e.error.phi));
        result.errors.push_back(e);

        translation.push_back(e.translation);
        rotation.push_back(e.rotationDeg);
        translationSquared.push_back(e.translation * e.translation);
        rotationSquared.push_back(e.rotationDeg * e.rotationDeg);
    }
    result.matchedRelations = result.errors.size();
    result.translation = summarizeErrors(translation);
    result.rotation = summarizeErrors(rotation);
    result.translationSquared = summarizeErrors(translationSquared);
    result.rotationSquared = summarizeErrors(rotationSquared);
    return result;
}

}  // namespace toposlam::evaluation
