#pragma once
// A laser log annotated with the features of every scan: reads any log LaserLogReader reads
// (CARMEN, MRPT rawlogs of either format) and writes a rawlog where each scan comes with its
// CObservationLaserFeatures (and its corners as a CObservationBearingRange), all with the
// scan's timestamp, in either of MRPT's formats:
//  - observations (default): per scan
//        [CObservationOdometry] CObservation2DRangeScan CObservationLaserFeatures
//        [CObservationBearingRange]
//    the odometry when the log has it, the corners with bearingRange;
//  - actions + sensory frames, what kf-slam and rbpf-slam read: per scan
//        CActionCollection{CActionRobotMovement2D}
//        CSensoryFrame{CObservation2DRangeScan, CObservationLaserFeatures,
//        CObservationBearingRange}
//    the action is the odometry increment since the previous scan (zero for the first one,
//    and where the log has no odometry) with `motionNoise` (MRPT's Gaussian model); the corners are
//    always there (possibly none: kf-slam needs a CObservationBearingRange in every frame).
// Output is atomic (nothing is left behind on error) and gzip-compressed when the name ends in
// ".gz". What toposlam-annotate-features does.
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <toposlam/features/FeatureExtractor.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/io/ProgressCallback.h>
#include <toposlam/io/RawlogWriter.h>

#include <cstddef>
#include <functional>
#include <string>

namespace toposlam::features {

/// MRPT's Gaussian odometry model in plain units (CActionRobotMovement2D's own fields mix
/// degrees and radians): per odometry increment of length d (m) and turn a (deg),
///   std of x and y = minXY + a1 * d + a2 * a        (m)
///   std of yaw     = minPhi + a3 * d + a4 * a       (deg)
struct MotionNoise {
    double a1 = 0.01;     ///< m per m
    double a2 = 0.001;    ///< m per deg
    double a3 = 1.0;      ///< deg per m
    double a4 = 0.05;     ///< deg per deg
    double minXY = 0.01;  ///< m
    double minPhi = 0.2;  ///< deg
    /// Throws std::invalid_argument unless every value is finite, >= 0, and minXY, minPhi > 0.
    void validate() const;
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions toMrpt() const;
};

struct LogAnnotationOptions {
    io::LaserLogOptions read;
    io::RawlogFormat format = io::RawlogFormat::Observations;
    /// Observations format: also write the corners as CObservationBearingRange (the
    /// sensory-frames format always does).
    bool bearingRange = false;
    /// Sensory-frames format: the odometry noise of the actions (defaults: MRPT's).
    MotionNoise motionNoise;
    /// Labels: the scan's label (or "LASER" if it has none) + these suffixes ("FLASER" ->
    /// "FLASER_FEATURES").
    std::string featuresLabelSuffix = "_FEATURES";
    std::string cornersLabelSuffix = "_CORNERS";
    std::size_t maxScans = 0;  ///< 0 = all
    /// Called after each scan with (fraction of the input read, scans so far).
    io::ProgressCallback progress;
    /// Called after each scan's extraction with the scan's record and its features (sensor
    /// frame), e.g. to build a feature map on the way.
    std::function<void(const io::LaserLogRecord&, const ScanFeatures&)> onScan;
};

struct LogAnnotationSummary {
    io::LaserLogFormat inputFormat = io::LaserLogFormat::Carmen;
    std::size_t scans = 0;
    std::size_t objects = 0;                               ///< top-level objects written
    std::size_t segments = 0, corners = 0, endpoints = 0;  ///< totals
    double extractionSeconds = 0;                          ///< time spent in the extractor
    /// RMS over every corner of its range (m) and bearing (rad) standard deviation, from the
    /// corner covariances (CornerBearingRange): what a landmark filter should assume as the
    /// sensor noise (kf-slam's std_sensor_range / std_sensor_yaw_deg). 0 without corners.
    double cornerRangeStd = 0, cornerBearingStd = 0;
};

/// Throws io::InputError for bad input (and for a log without laser scans) and
/// std::runtime_error when the output cannot be written.
LogAnnotationSummary annotateLog(const std::string& inputPath, const std::string& outputPath,
                                 FeatureExtractor& extractor,
                                 const LogAnnotationOptions& options = {});

}  // namespace toposlam::features
