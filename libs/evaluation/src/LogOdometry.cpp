#include <toposlam/evaluation/LogOdometry.h>
#include <toposlam/io/InputError.h>
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/io/ProgressDisplay.h>

#include <filesystem>

namespace toposlam::evaluation {

namespace {

// Streams the log once, calling visit(record) per scan, with progress on a terminal.
template <typename Visit>
void forEachScan(const std::string& logPath, Visit visit) {
    io::LaserLogReader reader(logPath);
    io::ProgressDisplay progress("reading " + std::filesystem::path(logPath).filename().string(),
                                 "scans");
    io::LaserLogRecord record;
    std::size_t scans = 0;
    while (reader.next(record)) {
        visit(record);
        progress.update(reader.fractionRead(), ++scans);
    }
    progress.finish();
}

}  // namespace

io::Trajectory2D odometryAtScans(const std::string& logPath) {
    io::Trajectory2D trajectory;
    forEachScan(logPath, [&](const io::LaserLogRecord& r) {
        if (r.hasOdometry)
            trajectory.push_back({r.fileStamp, r.odometry.asTPose()});
    });
    if (trajectory.empty())
        throw io::InputError(logPath, "no odometry in the log");
    return trajectory;
}

std::vector<double> scanFileStamps(const std::string& logPath) {
    std::vector<double> stamps;
    forEachScan(logPath, [&](const io::LaserLogRecord& r) { stamps.push_back(r.fileStamp); });
    return stamps;
}

}  // namespace toposlam::evaluation
