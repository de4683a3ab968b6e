#include <toposlam/evaluation/AlongTrackScale.h>

#include <cmath>

namespace toposlam::evaluation {

AlongTrackScale alongTrackScale(const PoseRelations& relations,
                                const RelativePoseErrorResult& scored) {
    AlongTrackScale out;
    for (const RelationError& e : scored.errors) {
        const PoseRelation& relation = relations[e.relation];
        const mrpt::math::TPose2D& truth = relation.motion;
        const double length = std::hypot(truth.x, truth.y);
        if (!(length >= kAlongTrackMinLength && length <= kAlongTrackMaxLength) ||
            !(std::abs(relation.stamp2 - relation.stamp1) <= kAlongTrackMaxSeconds)) {
            continue;
        }
        // e = δ_gt⁻¹ ⊕ δ_est, so δ_est = δ_gt ⊕ e (TPose2D's + is MRPT's ⊕).
        const mrpt::math::TPose2D estimated = truth + e.error;
        out.error +=
            ((estimated.x - truth.x) * truth.x + (estimated.y - truth.y) * truth.y) / length;
        out.pathLength += length;
        ++out.relations;
    }
    return out;
}

}  // namespace toposlam::evaluation
