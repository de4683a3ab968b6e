#include <mrpt/core/Clock.h>
#include <mrpt/math/wrap2pi.h>
#include <toposlam/io/AtomicFile.h>
#include <toposlam/simulation/LogSimulator.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace toposlam::simulation {

using mrpt::poses::CPose2D;

namespace {

io::Trajectory2D checkedAndRounded(io::Trajectory2D gt) {
    if (gt.empty())
        throw std::invalid_argument("the trajectory has no pose");
    for (std::size_t i = 0; i < gt.size(); ++i) {
        // The rawlog stores MRPT timestamps (100 ns ticks): give the ground truth the very same
        // values, so that stamps match exactly when the log is read back.
        gt[i].stamp = mrpt::Clock::toDouble(mrpt::Clock::fromDouble(gt[i].stamp));
        if (i > 0 && !(gt[i].stamp > gt[i - 1].stamp)) {
            throw std::invalid_argument(
                "pose " + std::to_string(i + 1) + ": timestamps must increase strictly (" +
                std::to_string(gt[i - 1].stamp) + " then " + std::to_string(gt[i].stamp) + ")");
        }
    }
    return gt;
}

}  // namespace

LogSimulator::LogSimulator(const mrpt::maps::COccupancyGridMap2D& map, io::Trajectory2D groundTruth,
                           const LogSimulationOptions& options)
    : options_(options),
      groundTruth_(checkedAndRounded(std::move(groundTruth))),
      world_(map, options.world),
      clearance_(map, options.world.thresholds),
      odometry_(options.odometry),
      laserRng_(options.seed),
      odometryRng_(options.seed + 1),
      stallRng_(options.seed + 3) {
    if (options.people.count > 0) {
        const auto& p0 = groundTruth_.front().pose;
        people_ = std::make_unique<MovingObstacles>(
            clearance_, options.people, mrpt::math::TPoint2D(p0.x, p0.y), options.seed + 2);
    }
}

LogSimulator::~LogSimulator() = default;

bool LogSimulator::next(io::LaserLogRecord& record) {
    if (next_ >= groundTruth_.size())
        return false;
    const io::TimedPose2D& now = groundTruth_[next_];
    const CPose2D pose(now.pose);

    if (next_ > 0) {
        const io::TimedPose2D& before = groundTruth_[next_ - 1];
        // Odometry: the true motion since the previous scan, in small steps along a constant
        // velocity arc between the two poses.
        const CPose2D motion = pose - CPose2D(before.pose);
        const double dist = std::hypot(motion.x(), motion.y());
        const int steps = std::max(
            {1, static_cast<int>(std::ceil(dist / options_.odometryStep)),
             static_cast<int>(std::ceil(std::abs(motion.phi()) / options_.odometryStepAngle))});
        CPose2D previous(before.pose);
        for (int k = 1; k <= steps; ++k) {
            const double f = static_cast<double>(k) / steps;
            const CPose2D sub(
                before.pose.x + f * (now.pose.x - before.pose.x),
                before.pose.y + f * (now.pose.y - before.pose.y),
                before.pose.phi + f * mrpt::math::wrapToPi(now.pose.phi - before.pose.phi));
            odometry_.move(sub - previous, odometryRng_);
            previous = sub;
        }
        if (people_) {
            people_->advance(now.stamp - before.stamp, {now.pose.x, now.pose.y});
        }
    }
    if (people_)
        world_.discs() = people_->discs();

    auto scan = std::make_shared<mrpt::obs::CObservation2DRangeScan>(
        simulateScan(world_, options_.laser, pose, laserRng_));
    scan->timestamp = mrpt::Clock::fromDouble(now.stamp);
    record.index = next_;
    record.fileStamp = now.stamp;
    record.scan = scan;
    record.odometry = odometryReading();
    record.hasOdometry = true;
    ++next_;
    return true;
}

CPose2D LogSimulator::odometryReading() {
    if (stalledScans_ > 0) {
        --stalledScans_;
        if (options_.odometry.stallHeadingReads)
            return {stalledReading_.x(), stalledReading_.y(), odometry_.pose().phi()};
        return stalledReading_;
    }
    // A fresh reading, which the next 1 to stallMaxScans scans may repeat: the reading after
    // them carries all the motion since.
    stalledReading_ = odometry_.pose();
    const OdometryErrorModel& model = options_.odometry;
    if (model.stallProbability > 0 &&
        std::uniform_real_distribution<double>(0, 1)(stallRng_) < model.stallProbability)
        stalledScans_ = std::uniform_int_distribution<int>(1, model.stallMaxScans)(stallRng_);
    return stalledReading_;
}

std::size_t simulateLogToFiles(const mrpt::maps::COccupancyGridMap2D& map,
                               const io::Trajectory2D& groundTruth,
                               const LogSimulationOptions& options, const std::string& rawlogPath,
                               io::RawlogFormat format, const std::string& groundTruthPath,
                               const io::ProgressCallback& progress) {
    LogSimulator sim(map, groundTruth, options);
    io::RawlogWriter writer(rawlogPath, format);
    io::LaserLogRecord record;
    std::size_t written = 0;
    while (sim.next(record)) {
        writer.write(record);
        ++written;
        if (progress)
            progress(static_cast<double>(written) / static_cast<double>(sim.size()), written);
    }
    io::OutputGroup files;  // both files or neither
    io::saveTrajectory(sim.groundTruth(), groundTruthPath);
    writer.commit();
    files.commit();
    return written;
}

}  // namespace toposlam::simulation
