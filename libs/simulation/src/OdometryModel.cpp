#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>
#include <toposlam/simulation/OdometryModel.h>

#include <cmath>

namespace toposlam::simulation {

namespace {
constexpr double kShortStep = 0.01;        ///< m
constexpr double kOffHeading = M_PI / 90;  ///< rad (2 deg)
}  // namespace

OdometryErrorModel OdometryErrorModel::exact() {
    OdometryErrorModel m;
    m.distanceScale = m.rotationScale = 1.0;
    m.curvaturePerMetre = m.alpha1 = m.alpha2 = m.alpha3 = m.alpha4 = 0.0;
    return m;
}

void OdometryErrorModel::declare(config::OptionsSchema& s) {
    // Variances in code, standard deviations in the file.
    const auto squaredDegrees = [](double deg) { return mrpt::square(mrpt::DEG2RAD(deg)); };
    const auto degrees = [](double variance) { return mrpt::RAD2DEG(std::sqrt(variance)); };
    const auto squared = [](double v) { return v * v; };
    const auto root = [](double variance) { return std::sqrt(variance); };
    s.real("distance_scale", distanceScale, "", "measured / true distance (1 = exact)").above(0);
    s.real("rotation_scale", rotationScale, "", "measured / true rotation (1 = exact)").above(0);
    s.converted(
        "curvature_deg_per_m", curvaturePerMetre, [](double v) { return mrpt::DEG2RAD(v); },
        [](double v) { return mrpt::RAD2DEG(v); }, "deg/m",
        "spurious rotation per metre driven (unequal wheels: a straight run curves)");
    s.converted("rot_std_deg_per_sqrt_rad", alpha1, squaredDegrees, degrees, "deg/sqrt(rad)",
                "heading error std after turning 1 rad")
        .atLeast(0);
    s.converted("rot_std_deg_per_sqrt_m", alpha2, squaredDegrees, degrees, "deg/sqrt(m)",
                "heading error std after driving 1 m")
        .atLeast(0);
    s.converted("trans_std_m_per_sqrt_m", alpha3, squared, root, "m/sqrt(m)",
                "distance error std after driving 1 m")
        .atLeast(0);
    s.converted("trans_std_m_per_sqrt_rad", alpha4, squared, root, "m/sqrt(rad)",
                "distance error std after turning 1 rad")
        .atLeast(0);
    s.real("stall_probability", stallProbability, "",
           "chance per fresh reading that the odometry freezes after it (a stall; 0 = never)")
        .within(0, 1);
    s.integer("stall_max_scans", stallMaxScans, "scans",
              "a stall repeats that reading for the next 1 to this many scans, then catches up")
        .within(1, 1000);
    s.flag("stall_heading_reads", stallHeadingReads,
           "during a stall only the position freezes, the heading still reads");
}

OdometryModel::OdometryModel(const OdometryErrorModel& model, const mrpt::poses::CPose2D& start)
    : model_(model), pose_(start) {}

mrpt::poses::CPose2D OdometryModel::measureIncrement(const mrpt::poses::CPose2D& inc,
                                                     std::mt19937& rng) {
    // rot1 / trans / rot2 decomposition; a backwards motion is a negative translation, so
    // rot1 never flips by pi for a robot that reverses.
    double trans = std::hypot(inc.x(), inc.y());
    double rot1 = 0;
    if (trans > 1e-9) {
        rot1 = std::atan2(inc.y(), inc.x());
        if (std::abs(rot1) > M_PI / 2) {
            rot1 = mrpt::math::wrapToPi(rot1 - M_PI);
            trans = -trans;
        }
        // A step of millimetres off the heading while turning (a twitch between two close
        // stops) is no drive in that direction: taken as rot1 and back as rot2, it would charge
        // up to twice 90 degrees of wheel turning, and its noise, to a step that turned a few.
        if (std::abs(trans) < kShortStep && std::abs(rot1) > kOffHeading)
            rot1 = 0;
    }
    const double rot2 = mrpt::math::wrapToPi(inc.phi() - rot1);
    const double absTrans = std::abs(trans);
    const double absRot = std::abs(rot1) + std::abs(rot2);

    const auto noise = [&](double variance) {
        return variance > 0 ? std::sqrt(variance) * gauss_(rng) : 0.0;
    };
    // Rotation noise and curvature bias are split between rot1 and rot2 so that their sum has
    // the documented mean and variance.
    const auto rotReading = [&](double rot) {
        return rot * model_.rotationScale + 0.5 * model_.curvaturePerMetre * trans +
               noise(model_.alpha1 * std::abs(rot) + 0.5 * model_.alpha2 * absTrans);
    };
    const double r1 = rotReading(rot1);
    const double t =
        trans * model_.distanceScale + noise(model_.alpha3 * absTrans + model_.alpha4 * absRot);
    const double r2 = rotReading(rot2);
    return mrpt::poses::CPose2D(t * std::cos(r1), t * std::sin(r1), r1 + r2);
}

const mrpt::poses::CPose2D& OdometryModel::move(const mrpt::poses::CPose2D& trueIncrement,
                                                std::mt19937& rng) {
    pose_ = pose_ + measureIncrement(trueIncrement, rng);
    pose_.normalizePhi();
    return pose_;
}

}  // namespace toposlam::simulation
