#pragma once
// Corners as range-bearing landmark observations (mrpt::obs::CObservationBearingRange), the
// input of MRPT's own landmark SLAM (kf-slam, CRangeBearingKFSLAM2D) and of any code written
// for MRPT's bearing-range sensors.
// Each corner becomes one measurement: range (m) and yaw (rad) from the sensor, pitch 0, and
// its covariance in (range, yaw, pitch), propagated from the corner's Cartesian covariance
// (validCovariances = true). sensor_std_range / sensor_std_yaw are set to the RMS of the
// per-corner standard deviations, for consumers that use one noise level for all.
// Landmark IDs: -1 (unknown: data association is the consumer's job) unless ids are given.
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <toposlam/features/ScanFeatures.h>

#include <cstdint>
#include <vector>

namespace toposlam::features {

struct CornerBearingRangeOptions {
    std::string sensorLabel = "CORNERS";
    /// Variance given to pitch (rad^2): planar features, but the matrix must stay invertible.
    double pitchVariance = 1e-6;
};

/// Fills `out` from the corners of `features` (sensor frame). The sensor pose, time stamp
/// and field of view are taken from `scan`, the scan the features came from. `landmarkIds`:
/// one per corner, or empty for -1 (unknown).
void cornersToBearingRange(const ScanFeatures& features,
                           const mrpt::obs::CObservation2DRangeScan& scan,
                           mrpt::obs::CObservationBearingRange& out,
                           const std::vector<std::int32_t>& landmarkIds = {},
                           const CornerBearingRangeOptions& options = {});

}  // namespace toposlam::features
