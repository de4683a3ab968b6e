#pragma once
// Online calibration of the wheel odometry's distance scale: how far the robot moved per metre
// the odometry reports, learnt from the scans that ICP placed with every direction determined.
//
// Why: where the laser fixes nothing along the robot's way (a corridor), registration keeps
// much of the odometry's prediction along it. An odometry that over-reads distance by 1 %
// then stretches every long corridor (a fifth of that error stayed in the map on Bormann's
// long office plans), and one that over-reads by about 5 % (intel's) lets the trajectory fall
// behind along a corridor when loops are searched less often. With the prediction scaled by
// what the well-registered scans show, what registration keeps along a corridor is the truth.
// (Odometry calibration from scan matching: e.g. Censi et al., "Simultaneous calibration of
// odometry and sensor parameters for mobile robots", IEEE T-RO 2013.)
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/poses/CPose2D.h>

namespace toposlam::mapping {

class OdometryCalibration {
  public:
    struct Options {
        /// Off by default (config_ini/toposlam-slam.ini, odometry_calibration, says why).
        bool enabled = false;
        /// Metres of well-registered odometry before the scale is applied (a few scans say
        /// little: their registration noise is a large share of their motion).
        double minDistance = 10.0;
        /// A registration counts when its worst position standard deviation (ICP's covariance,
        /// m) is at most this: the scan fixed the robot along its way as well as across.
        double maxStd = 0.01;
        /// The scale stays within 1 +- this (an odometry off by more is broken, not biased).
        double maxCorrection = 0.1;
    };

    explicit OdometryCalibration(const Options& options) : options_(options) {}

    /// `increment` (robot frame of the previous scan: m, m, rad) with its translation scaled
    /// by scale(); the turn is left as it is (the laser fixes headings well everywhere).
    mrpt::poses::CPose2D corrected(const mrpt::poses::CPose2D& increment) const;

    /// One registered scan: the odometry's raw increment since the previous scan, the motion
    /// registration found over the same scans (both in the previous scan's robot frame) and
    /// registration's covariance of (x, y, phi) (m^2, rad^2). Least squares over all such
    /// scans: scale = sum(registered . odometry) / sum(|odometry|^2). Counted also when not
    /// enabled (estimate() then says what the calibration would do; scale() stays 1).
    void observe(const mrpt::poses::CPose2D& odometry, const mrpt::poses::CPose2D& registered,
                 const mrpt::math::CMatrixDouble33& covariance);

    /// Registered distance per odometry distance in use: 1 until minDistance of evidence.
    double scale() const;
    /// The estimate from the evidence so far, whether in use or not (1 without evidence).
    double estimate() const;
    /// Odometry distance (m) of the scans that counted.
    double evidenceDistance() const { return distance_; }

  private:
    Options options_;
    double motionDotOdometry_ = 0;  ///< sum of registered . odometry (m^2)
    double odometrySquared_ = 0;    ///< sum of |odometry|^2 (m^2)
    double distance_ = 0;           ///< sum of |odometry| (m)
};

}  // namespace toposlam::mapping
