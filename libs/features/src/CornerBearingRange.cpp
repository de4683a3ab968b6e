#include <toposlam/features/CornerBearingRange.h>

#include <cmath>
#include <stdexcept>

namespace toposlam::features {

void cornersToBearingRange(const ScanFeatures& features,
                           const mrpt::obs::CObservation2DRangeScan& scan,
                           mrpt::obs::CObservationBearingRange& out,
                           const std::vector<std::int32_t>& landmarkIds,
                           const CornerBearingRangeOptions& options) {
    if (!landmarkIds.empty() && landmarkIds.size() != features.corners.size()) {
        throw std::invalid_argument("cornersToBearingRange: " + std::to_string(landmarkIds.size()) +
                                    " landmark ids for " + std::to_string(features.corners.size()) +
                                    " corners");
    }
    out.timestamp = scan.timestamp;
    out.sensorLabel = options.sensorLabel;
    out.sensorLocationOnRobot = scan.sensorPose;
    out.minSensorDistance = 0;
    out.maxSensorDistance = scan.maxRange;
    out.fieldOfView_yaw = scan.aperture;
    out.fieldOfView_pitch = 0;
    out.validCovariances = true;
    out.sensedData.clear();
    out.sensedData.reserve(features.corners.size());

    double sumVarRange = 0, sumVarYaw = 0;
    for (std::size_t i = 0; i < features.corners.size(); ++i) {
        const Corner& c = features.corners[i];
        const double x = c.position.x, y = c.position.y;
        const double r2 = x * x + y * y, r = std::sqrt(r2);
        mrpt::obs::CObservationBearingRange::TMeasurement m;
        m.range = static_cast<float>(r);
        m.yaw = static_cast<float>(std::atan2(y, x));
        m.pitch = 0;
        m.landmarkID = landmarkIds.empty() ? -1 : landmarkIds[i];
        // J = d(range, yaw)/d(x, y) = [x/r, y/r; -y/r^2, x/r^2]; C' = J C J^T.
        const double a = c.covariance(0, 0), b = c.covariance(0, 1), d = c.covariance(1, 1);
        const double j00 = x / r, j01 = y / r, j10 = -y / r2, j11 = x / r2;
        const double varRange = j00 * j00 * a + 2 * j00 * j01 * b + j01 * j01 * d;
        const double cov = j00 * j10 * a + (j00 * j11 + j01 * j10) * b + j01 * j11 * d;
        const double varYaw = j10 * j10 * a + 2 * j10 * j11 * b + j11 * j11 * d;
        m.covariance.setZero();
        m.covariance(0, 0) = varRange;
        m.covariance(0, 1) = m.covariance(1, 0) = cov;
        m.covariance(1, 1) = varYaw;
        m.covariance(2, 2) = options.pitchVariance;
        sumVarRange += varRange;
        sumVarYaw += varYaw;
        out.sensedData.push_back(m);
    }
    const double n = static_cast<double>(features.corners.size());
    out.sensor_std_range = n > 0 ? static_cast<float>(std::sqrt(sumVarRange / n)) : 0.f;
    out.sensor_std_yaw = n > 0 ? static_cast<float>(std::sqrt(sumVarYaw / n)) : 0.f;
    out.sensor_std_pitch = static_cast<float>(std::sqrt(options.pitchVariance));
}

}  // namespace toposlam::features
