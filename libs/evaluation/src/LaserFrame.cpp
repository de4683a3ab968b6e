#include <toposlam/evaluation/LaserFrame.h>
#include <toposlam/evaluation/LogOdometry.h>
#include <toposlam/evaluation/StampedPoseLookup.h>
#include <toposlam/io/LaserPosition.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace toposlam::evaluation {

io::Trajectory2D laserPositionsAtScans(const std::string& logPath,
                                       const io::ProgressCallback& progress) {
    return readLogScans(logPath, progress).laserPositions;
}

namespace {

double median(std::vector<double>& values) {
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

}  // namespace

mrpt::math::TPoint2D typicalLaserPosition(const io::Trajectory2D& laserPositions) {
    if (laserPositions.empty())
        return {0, 0};
    std::vector<double> xs, ys;
    xs.reserve(laserPositions.size());
    ys.reserve(laserPositions.size());
    for (const io::TimedPose2D& p : laserPositions) {
        xs.push_back(p.pose.x);
        ys.push_back(p.pose.y);
    }
    return {median(xs), median(ys)};
}

bool laserOffCentre(const io::Trajectory2D& laserPositions) {
    return std::any_of(laserPositions.begin(), laserPositions.end(), [](const io::TimedPose2D& p) {
        return io::laserOffCentre({p.pose.x, p.pose.y});
    });
}

io::Trajectory2D inLaserFrame(const io::Trajectory2D& robotPoses,
                              const io::Trajectory2D& laserPositions, double stampTolerance) {
    const StampedPoseLookup scans(laserPositions, stampTolerance);
    const mrpt::math::TPoint2D typical = typicalLaserPosition(laserPositions);
    io::Trajectory2D laser;
    laser.reserve(robotPoses.size());
    for (const io::TimedPose2D& p : robotPoses) {
        const auto scan = scans.find(p.stamp);
        const double x = scan ? laserPositions[*scan].pose.x : typical.x;
        const double y = scan ? laserPositions[*scan].pose.y : typical.y;
        const double c = std::cos(p.pose.phi), s = std::sin(p.pose.phi);
        laser.push_back(
            {p.stamp, {p.pose.x + c * x - s * y, p.pose.y + s * x + c * y, p.pose.phi}});
    }
    return laser;
}

}  // namespace toposlam::evaluation
