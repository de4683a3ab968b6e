#include <toposlam/matching/CScanFeaturesMap.h>
#include <toposlam/mrptslam/CGraphMatcherAlignment.h>
#include <Eigen/Dense>

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace toposlam::mrptslam {

using matching::CScanFeaturesMap;
using matching::GraphMatcherOptions;
using matching::MatchResult;
using matching::MatchStatus;
using mrpt::poses::CPose2D;

CGraphMatcherAlignment::CGraphMatcherAlignment() {
    setLoggerName("CGraphMatcherAlignment");
}

void CGraphMatcherAlignment::Options::declare(config::OptionsSchema& s) {
    s.group("", matcher);
    s.flag("use_guess", useGuess,
           "CGraphMatcherAlignment: prune with the guess (false: guess-free, loop closure)");
    s.real("unreliable_variance", unreliableVariance, "m^2, rad^2",
           "CGraphMatcherAlignment: covariance returned for a non-reliable match")
        .above(0);
}

namespace {
const CScanFeaturesMap& asFeatureMap(const mrpt::maps::CMetricMap* m, const char* which) {
    const auto* f = dynamic_cast<const CScanFeaturesMap*>(m);
    if (!f)
        throw std::invalid_argument(std::string("CGraphMatcherAlignment: map ") + which +
                                    " is not a toposlam::matching::CScanFeaturesMap");
    return *f;
}

/// Map-frame pose X (m2 in m1) from the sensor-frame match T: X = S1 + T - S2.
CPose2D toMapFrames(const CPose2D& s1, const CPose2D& t, const CPose2D& s2) {
    return s1 + t + (-s2);
}
}  // namespace

mrpt::poses::CPosePDF::Ptr CGraphMatcherAlignment::AlignPDF(
    const mrpt::maps::CMetricMap* m1, const mrpt::maps::CMetricMap* m2,
    const mrpt::poses::CPosePDFGaussian& initial,
    mrpt::optional_ref<mrpt::slam::TMetricMapAlignmentResult> outInfo) {
    const auto start = std::chrono::steady_clock::now();
    const CScanFeaturesMap& ref = asFeatureMap(m1, "m1");
    const CScanFeaturesMap& cur = asFeatureMap(m2, "m2");
    const CPose2D s1 = ref.sensorPose(), s2 = cur.sensorPose();

    GraphMatcherOptions o = options.matcher;
    std::optional<CPose2D> guess;
    if (options.useGuess) {
        // The guess is m2 in m1; the matcher wants the current sensor in the reference one.
        guess = (-s1) + initial.mean + s2;
        const double sx = std::sqrt(std::max(0.0, initial.cov(0, 0)));
        const double sy = std::sqrt(std::max(0.0, initial.cov(1, 1)));
        const double sphi = std::sqrt(std::max(0.0, initial.cov(2, 2)));
        o.guessTranslationWindow = std::max(o.guessTranslationWindow, 3 * std::hypot(sx, sy));
        o.guessRotationWindow = std::min(M_PI, std::max(o.guessRotationWindow, 3 * sphi));
    }
    matcher_.options() = o;
    const MatchResult& r =
        matcher_.match(ref.polar(), ref.features(), cur.polar(), cur.features(), guess);

    auto pdf = mrpt::poses::CPosePDFGaussian::Create();
    const bool havePose = r.status != MatchStatus::TooFewFeatures && r.candidates > 0;
    pdf->mean = havePose ? toMapFrames(s1, r.pose, s2) : initial.mean;
    if (r.reliable()) {
        // Covariance of X = S1 + T - S2 by the Jacobian of T -> X (central differences).
        mrpt::math::CMatrixDouble33 J;
        const double h = 1e-6;
        for (int k = 0; k < 3; ++k) {
            double d[3] = {0, 0, 0};
            d[k] = h;
            const CPose2D tp(r.pose.x() + d[0], r.pose.y() + d[1], r.pose.phi() + d[2]);
            const CPose2D tm(r.pose.x() - d[0], r.pose.y() - d[1], r.pose.phi() - d[2]);
            const CPose2D xp = toMapFrames(s1, tp, s2), xm = toMapFrames(s1, tm, s2);
            J(0, k) = (xp.x() - xm.x()) / (2 * h);
            J(1, k) = (xp.y() - xm.y()) / (2 * h);
            J(2, k) = mrpt::math::wrapToPi(xp.phi() - xm.phi()) / (2 * h);
        }
        pdf->cov = mrpt::math::CMatrixDouble33(J.asEigen() * r.covariance.asEigen() *
                                               J.asEigen().transpose());
    } else {
        pdf->cov.setIdentity();
        pdf->cov *= options.unreliableVariance;
    }

    if (outInfo) {
        outInfo->get().executionTime =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (auto* info = dynamic_cast<TGraphMatcherAlignmentResult*>(&outInfo->get())) {
            info->match = r;
            info->mapPose = pdf->mean;
        }
    }
    return pdf;
}

mrpt::poses::CPose3DPDF::Ptr CGraphMatcherAlignment::Align3DPDF(
    const mrpt::maps::CMetricMap* m1, const mrpt::maps::CMetricMap* m2,
    const mrpt::poses::CPose3DPDFGaussian& initial,
    mrpt::optional_ref<mrpt::slam::TMetricMapAlignmentResult> outInfo) {
    mrpt::poses::CPosePDFGaussian initial2D;
    initial2D.mean = CPose2D(initial.mean);
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 2; ++c)
            initial2D.cov(r, c) = initial.cov(r, c);
    initial2D.cov(2, 2) = initial.cov(3, 3);  // 3D order: x y z yaw pitch roll
    initial2D.cov(0, 2) = initial2D.cov(2, 0) = initial.cov(0, 3);
    initial2D.cov(1, 2) = initial2D.cov(2, 1) = initial.cov(1, 3);
    const auto pdf2D = AlignPDF(m1, m2, initial2D, outInfo);
    const auto& g = dynamic_cast<const mrpt::poses::CPosePDFGaussian&>(*pdf2D);
    auto out = mrpt::poses::CPose3DPDFGaussian::Create();
    out->copyFrom(g);
    return out;
}

}  // namespace toposlam::mrptslam
