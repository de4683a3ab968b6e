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
        // e = δ_gt⁻¹ ⊕ δ_est has translation R(−φ_gt) (t_est − t_gt): turn it back.
        const double c = std::cos(truth.phi), s = std::sin(truth.phi);
        const double dx = c * e.error.x - s * e.error.y, dy = s * e.error.x + c * e.error.y;
        out.error += (dx * truth.x + dy * truth.y) / length;
        out.pathLength += length;
        ++out.relations;
    }
    return out;
}

}  // namespace toposlam::evaluation
