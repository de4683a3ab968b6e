#pragma once
// Wheel odometry with realistic drift. Each true motion increment between two odometry readings
// is decomposed as in Thrun, Burgard & Fox, Probabilistic Robotics (2005), sec. 5.4: a rotation
// rot1 towards the direction of travel, a translation trans, a final rotation rot2 (rot1 = 0 for
// a step under 1 cm whose direction is more than 2 deg off the heading: millimetres of drift
// while turning are no drive in that direction). The reading then gets two kinds of error:
//
//  * systematic (the same every time; Borenstein & Feng's UMBmark error sources):
//      trans' = trans * distanceScale              (mean wheel radius wrong)
//      rot'   = rot * rotationScale                (effective wheelbase wrong)
//             + curvaturePerMetre * trans          (left/right wheel radii differ: the robot
//                                                   believes it curves while driving straight)
//  * random, zero-mean Gaussian, whose VARIANCE grows linearly with the motion (alpha1..alpha4
//    play the roles of Thrun's):
//      var(rotation error)    = alpha1 * |rot|   + alpha2 * |trans|   (split over rot1, rot2)
//      var(translation error) = alpha3 * |trans| + alpha4 * |rot|
//    Thrun's model uses squared increments, which makes the drift vanish as the odometry rate
//    grows; with linear variances the drift after a path is the same however finely it is
//    sampled: after driving D metres straight, the heading error has std sqrt(alpha2 * D) and
//    the distance error std sqrt(alpha3 * D).
//
// Defaults: a well-maintained indoor differential-drive robot (Pioneer-class) on a hard floor:
// 1 % distance scale error, 1.5 % rotation scale error (1.35 deg per 90 deg turn), 0.1 deg/m
// curvature; random errors of 1.5 cm and 0.5 deg after 1 m, 1.5 deg after a full 1 rad turn.
// Over a 100 m office tour that is a few metres and tens of degrees of accumulated drift, as
// raw logs of real robots show.
#include <mrpt/core/bits_math.h>
#include <mrpt/poses/CPose2D.h>
#include <toposlam/config/Options.h>

#include <random>
#include <string>

namespace toposlam::simulation {

/// Section [Odometry] of config_ini/sim-office.ini: the file states the random errors as the
/// standard deviation after one unit of motion (deg or m per sqrt(rad) / sqrt(m)).
struct OdometryErrorModel : public config::Options {
    double distanceScale = 1.01;   ///< measured / true distance (1 = exact)
    double rotationScale = 1.015;  ///< measured / true rotation (1 = exact)
    /// rad of spurious rotation per metre driven (0.1 deg/m)
    double curvaturePerMetre = mrpt::DEG2RAD(0.1);
    /// rad^2 of rotation variance per rad turned ((1.5 deg)^2)
    double alpha1 = mrpt::square(mrpt::DEG2RAD(1.5));
    /// rad^2 of rotation variance per m driven ((0.5 deg)^2)
    double alpha2 = mrpt::square(mrpt::DEG2RAD(0.5));
    double alpha3 = 0.015 * 0.015;  ///< m^2 of translation variance per m driven ((1.5 cm)^2)
    double alpha4 = 0.005 * 0.005;  ///< m^2 of translation variance per rad turned ((0.5 cm)^2)
    /// Stalls (a fault, not drift; used by LogSimulator): after each fresh reading, with this
    /// probability, the odometry freezes and the next 1 to stallMaxScans scans repeat that
    /// reading; the one after them reports the whole motion since, as logs whose odometry
    /// messages stop for a moment do (MIT CSAIL's). 0 = never.
    double stallProbability = 0;
    int stallMaxScans = 3;
    /// During a stall the heading still reads and only the distance freezes (the wheels'
    /// count stops while the gyro goes on, as in mit-csail's log: 0.004, 0 and 0 m read where
    /// the robot went 0.21 m each, the turn read all along).
    bool stallHeadingReads = false;

    /// Perfect odometry: readings equal the true motion.
    static OdometryErrorModel exact();
    void declare(config::OptionsSchema& s) override;
};

/// Integrates noisy odometry along the true motion of a robot.
class OdometryModel {
  public:
    /// Odometry starts at `start` (robots usually start their odometry at (0,0,0)).
    explicit OdometryModel(const OdometryErrorModel& model,
                           const mrpt::poses::CPose2D& start = mrpt::poses::CPose2D());

    /// Applies one true motion increment (robot frame of the previous pose, m and rad) and
    /// returns the new cumulative odometry (odometry frame). `rng` supplies the noise.
    const mrpt::poses::CPose2D& move(const mrpt::poses::CPose2D& trueIncrement, std::mt19937& rng);
    /// The increment the odometry reports for one true increment (no accumulation).
    mrpt::poses::CPose2D measureIncrement(const mrpt::poses::CPose2D& trueIncrement,
                                          std::mt19937& rng);

    const mrpt::poses::CPose2D& pose() const { return pose_; }
    const OdometryErrorModel& model() const { return model_; }

  private:
    OdometryErrorModel model_;
    mrpt::poses::CPose2D pose_;
    std::normal_distribution<double> gauss_{0.0, 1.0};
};

}  // namespace toposlam::simulation
