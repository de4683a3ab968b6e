#include <toposlam/evaluation/LogOdometry.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/LaserLogReader.h>

namespace toposlam::evaluation {

namespace {

// Streams the log once, calling visit(record) per scan.
template <typename Visit>
void forEachScan(const std::string& logPath, const io::ProgressCallback& progress, Visit visit) {
    io::LaserLogReader reader(logPath);
    io::LaserLogRecord record;
    std::size_t scans = 0;
    while (reader.next(record)) {
        visit(record);
        ++scans;
        if (progress)
            progress(reader.fractionRead(), scans);
    }
}

}  // namespace

io::Trajectory2D odometryAtScans(const std::string& logPath, const io::ProgressCallback& progress) {
    io::Trajectory2D trajectory;
    forEachScan(logPath, progress, [&](const io::LaserLogRecord& r) {
        if (r.hasOdometry)
            trajectory.push_back({r.fileStamp, r.odometry.asTPose()});
    });
    if (trajectory.empty())
        throw io::InputError(logPath, "no odometry in the log");
    return trajectory;
}

std::vector<double> scanFileStamps(const std::string& logPath,
                                   const io::ProgressCallback& progress) {
    std::vector<double> stamps;
    forEachScan(logPath, progress,
                [&](const io::LaserLogRecord& r) { stamps.push_back(r.fileStamp); });
    return stamps;
}

}  // namespace toposlam::evaluation
