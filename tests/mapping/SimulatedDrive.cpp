#include "SimulatedDrive.h"

#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPoint2D.h>
#include <mrpt/system/datetime.h>
#include <toposlam/evaluation/RigidAlignment2D.h>
#include <toposlam/io/RawlogWriter.h>

#include <cmath>
#include <random>

namespace toposlam::test {

using mrpt::poses::CPose2D;

std::vector<CPose2D> drivePath(const std::vector<mrpt::math::TPoint2D>& waypoints, double step,
                               double turnStep) {
    std::vector<CPose2D> poses;
    for (std::size_t w = 0; w + 1 < waypoints.size(); ++w) {
        const auto& a = waypoints[w];
        const auto& b = waypoints[w + 1];
        const double heading = std::atan2(b.y - a.y, b.x - a.x);
        if (!poses.empty()) {  // turn on the spot towards the next leg
            const double from = poses.back().phi();
            const double turn = mrpt::math::wrapToPi(heading - from);
            const int n = int(std::ceil(std::abs(turn) / turnStep));
            for (int k = 1; k < n; ++k)
                poses.emplace_back(a.x, a.y, mrpt::math::wrapToPi(from + turn * k / n));
        }
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        const int n = std::max(1, int(std::round(length / step)));
        for (int k = 0; k < n; ++k)
            poses.emplace_back(a.x + (b.x - a.x) * k / n, a.y + (b.y - a.y) * k / n, heading);
    }
    const auto& last = waypoints.back();
    poses.emplace_back(last.x, last.y, poses.empty() ? 0.0 : poses.back().phi());
    return poses;
}

SimulatedDrive simulateDrive(const simulation::PolygonWorld& world,
                             const std::vector<CPose2D>& truth, const OdometryErrors& errors,
                             unsigned seed, const simulation::LaserModel& laserIn) {
    simulation::LaserModel laser = laserIn;
    if (laser.rangeNoiseStd == 0)
        laser.rangeNoiseStd = 0.01;
    laser.maxRange = std::min(laser.maxRange, 20.0);
    std::mt19937 rng(seed);
    SimulatedDrive drive;
    drive.truth = truth;
    CPose2D odometry;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        if (i > 0) {
            const CPose2D step = truth[i] - truth[i - 1];
            const double d = step.norm();
            const double forward = errors.reversingReadsForward ? std::abs(step.x()) : step.x();
            odometry =
                odometry + CPose2D(forward * errors.distanceScale, step.y() * errors.distanceScale,
                                   step.phi() * errors.turnScale + errors.headingDriftPerMetre * d);
        }
        CPose2D reported = odometry;
        if (errors.jumpAt > 0 && i >= errors.jumpAt)
            reported = errors.jump + odometry;  // the odometry frame jumps
        drive.odometry.push_back(reported);
        auto scan = mrpt::obs::CObservation2DRangeScan::Create(
            simulation::simulateScan(world, laser, truth[i], rng));
        scan->timestamp = mrpt::Clock::fromDouble(1000.0 + 0.1 * double(i));
        drive.scans.push_back(scan);
    }
    return drive;
}

void writeRawlog(const SimulatedDrive& drive, const std::string& path) {
    io::RawlogWriter writer(path, io::RawlogFormat::Observations);
    for (std::size_t i = 0; i < drive.scans.size(); ++i) {
        io::LaserLogRecord rec;
        rec.index = i;
        rec.fileStamp = 1000.0 + 0.1 * double(i);
        rec.scan = drive.scans[i];
        rec.odometry = drive.odometry[i];
        rec.hasOdometry = true;
        writer.write(rec);
    }
    writer.commit();
}

double absoluteTrajectoryError(const std::vector<CPose2D>& truth,
                               const std::vector<CPose2D>& estimate) {
    std::vector<mrpt::math::TPoint2D> source, target;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        source.emplace_back(estimate[i].x(), estimate[i].y());
        target.emplace_back(truth[i].x(), truth[i].y());
    }
    const CPose2D t(evaluation::alignRigid2D(source, target));
    double sum = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        const auto p = t + mrpt::poses::CPoint2D(source[i].x, source[i].y);
        sum += std::pow(p.x() - target[i].x, 2) + std::pow(p.y() - target[i].y, 2);
    }
    return std::sqrt(sum / double(truth.size()));
}

}  // namespace toposlam::test
