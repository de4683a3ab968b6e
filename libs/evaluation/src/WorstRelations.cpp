#include <toposlam/evaluation/ErrorStatistics.h>
#include <toposlam/evaluation/SlamEvaluation.h>
#include <toposlam/evaluation/WorstRelations.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace toposlam::evaluation {

std::vector<WorstRelation> worstRelations(const RelativePoseErrorResult& result,
                                          const PoseRelations& relations, std::size_t count) {
    std::vector<const RelationError*> order;
    order.reserve(result.errors.size());
    for (const RelationError& e : result.errors)
        order.push_back(&e);
    const std::size_t n = std::min(count, order.size());
    std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n), order.end(),
                      [](const RelationError* a, const RelationError* b) {
                          return a->translation != b->translation ? a->translation > b->translation
                                                                  : a->relation < b->relation;
                      });
    std::vector<WorstRelation> worst;
    worst.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const RelationError& e = *order[i];
        const PoseRelation& r = relations.at(e.relation);
        WorstRelation w;
        w.relation = e.relation;
        w.stamp1 = r.stamp1;
        w.stamp2 = r.stamp2;
        w.reference = r.motion;
        w.estimate = r.motion + e.error;  // e = δ_gt⁻¹ ⊕ δ_est
        w.translation = e.translation;
        w.rotationDeg = e.rotationDeg;
        worst.push_back(w);
    }
    return worst;
}

namespace {

// The motion as "Δx, Δy m, Δyaw°".
std::string formatMotion(const mrpt::math::TPose2D& m) {
    return formatFixed(m.x, 3) + ", " + formatFixed(m.y, 3) + " m, " +
           formatFixed(m.phi * 180.0 / M_PI, 1) + "°";
}

// A method's translational error on relation `relation` ("–" if it did not match it); its
// errors are in relation order.
std::string errorOn(const MethodEvaluation& m, std::size_t relation) {
    const auto& errors = m.relative.errors;
    const auto it =
        std::lower_bound(errors.begin(), errors.end(), relation,
                         [](const RelationError& e, std::size_t r) { return e.relation < r; });
    return it != errors.end() && it->relation == relation ? formatFixed(it->translation, 3) + " m"
                                                          : std::string("–");
}

}  // namespace

std::string formatWorstRelations(const SlamEvaluation& ev) {
    std::ostringstream out;
    for (const MethodEvaluation& m : ev.methods) {
        if (m.worst.empty())
            continue;
        out << "\nWorst relations of " << m.name
            << " (largest translational error first; motion = pose at t2 in the frame of the "
               "pose at t1):\n\n| t1 (s) | t2 − t1 (s) | reference motion | "
            << "motion by " << m.name << " | error (m / °) |";
        for (const MethodEvaluation& other : ev.methods) {
            if (&other != &m)
                out << " " << other.name << " |";
        }
        out << "\n|---|---|---|---|---|";
        for (std::size_t i = 1; i < ev.methods.size(); ++i)
            out << "---|";
        out << "\n";
        for (const WorstRelation& w : m.worst) {
            out << "| " << formatFixed(w.stamp1, 3) << " | " << formatFixed(w.stamp2 - w.stamp1, 2)
                << " | " << formatMotion(w.reference) << " | " << formatMotion(w.estimate) << " | "
                << formatFixed(w.translation, 3) << " / " << formatFixed(w.rotationDeg, 2) << " |";
            for (const MethodEvaluation& other : ev.methods) {
                if (&other != &m)
                    out << " " << errorOn(other, w.relation) << " |";
            }
            out << "\n";
        }
    }
    return out.str();
}

}  // namespace toposlam::evaluation
