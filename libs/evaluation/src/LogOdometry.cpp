#include <toposlam/evaluation/LogOdometry.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/LaserLogReader.h>

#include <utility>

namespace toposlam::evaluation {

LogScans readLogScans(const std::string& logPath, const io::ProgressCallback& progress) {
    io::LaserLogReader reader(logPath);
    io::LaserLogRecord record;
    LogScans scans;
    while (reader.next(record)) {
        if (record.hasOdometry)
            scans.odometry.push_back({record.fileStamp, record.odometry.asTPose()});
        scans.laserPositions.push_back(
            {record.fileStamp, {record.scan->sensorPose.x(), record.scan->sensorPose.y(), 0.0}});
        if (progress)
            progress(reader.fractionRead(), scans.laserPositions.size());
    }
    return scans;
}

const io::Trajectory2D& odometryOf(const LogScans& scans, const std::string& logPath) {
    if (scans.odometry.empty())
        throw io::InputError(logPath, "no odometry in the log");
    return scans.odometry;
}

io::Trajectory2D odometryAtScans(const std::string& logPath, const io::ProgressCallback& progress) {
    LogScans scans = readLogScans(logPath, progress);
    odometryOf(scans, logPath);
    return std::move(scans.odometry);
}

}  // namespace toposlam::evaluation
