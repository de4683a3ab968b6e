#include <toposlam/io/InputError.h>
#include <toposlam/io/LogConversion.h>
#include <toposlam/io/Trajectory.h>

#include <memory>

namespace toposlam::io {

LogConversionSummary convertLaserLog(const std::string& inputPath,
                                     const LogConversionOptions& options) {
    LaserLogReader reader(inputPath, options.read);
    std::unique_ptr<RawlogWriter> writer;
    if (!options.rawlogPath.empty()) {
        writer = std::make_unique<RawlogWriter>(options.rawlogPath, options.rawlogFormat);
    }
    LogConversionSummary summary;
    summary.inputFormat = reader.format();
    Trajectory2D odometry;
    LaserLogRecord record;
    while ((options.maxScans == 0 || summary.scans < options.maxScans) && reader.next(record)) {
        if (summary.scans == 0) {
            summary.beamsPerScan = record.scan->getScanSize();
            summary.firstStamp = record.fileStamp;
        }
        summary.lastStamp = record.fileStamp;
        ++summary.scans;
        if (writer)
            writer->write(record);
        if (record.hasOdometry) {
            odometry.push_back({record.fileStamp, record.odometry.asTPose()});
        } else {
            ++summary.scansWithoutOdometry;
        }
        if (options.progress)
            options.progress(reader.fractionRead(), summary.scans);
    }
    if (summary.scans == 0) {
        throw InputError(
            inputPath, options.read.scanLabel.empty()
                           ? "no laser scans in the log"
                           : "no laser scans labelled '" + options.read.scanLabel + "' in the log");
    }
    summary.adjustedTimestamps = reader.adjustedTimestamps();
    // The trajectory first: if it cannot be written, the rawlog is not committed either.
    if (!options.odometryTrajectoryPath.empty()) {
        saveTrajectory(odometry, options.odometryTrajectoryPath);
    }
    if (writer) {
        summary.rawlogObjects = writer->objectCount();
        writer->commit();
    }
    return summary;
}

}  // namespace toposlam::io
