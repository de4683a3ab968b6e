#include <toposlam/io/InputError.h>
#include <toposlam/io/LogConversion.h>
#include <toposlam/io/MirrorImage.h>
#include <toposlam/io/Trajectory.h>

#include <algorithm>
#include <cstdio>
#include <memory>

namespace toposlam::io {

mrpt::obs::CObservation2DRangeScan::Ptr keepEveryBeam(
    const mrpt::obs::CObservation2DRangeScan& scan, std::size_t keepEvery) {
    auto out = std::make_shared<mrpt::obs::CObservation2DRangeScan>(scan);
    const std::size_t n = scan.getScanSize();
    if (keepEvery <= 1 || n < 2)
        return out;
    const std::size_t kept = (n - 1) / keepEvery + 1;
    out->resizeScan(kept);
    for (std::size_t k = 0; k < kept; ++k) {
        out->setScanRange(k, scan.getScanRange(k * keepEvery));
        out->setScanRangeValidity(k, scan.getScanRangeValidity(k * keepEvery));
        if (scan.hasIntensity())
            out->setScanIntensity(k, scan.getScanIntensity(k * keepEvery));
    }
    // Beam i of n points at -aperture/2 + i * aperture / (n - 1) (MRPT's convention, mirrored
    // for rightToLeft = false). The kept ones span (kept - 1) * keepEvery steps from the first
    // beam; a fan centred on the sensor's x axis needs the sensor turned by the shift.
    const double step = double(scan.aperture) / double(n - 1);
    const double span = step * double((kept - 1) * keepEvery);
    out->aperture = static_cast<float>(span);
    const double shift = (scan.rightToLeft ? 1.0 : -1.0) * 0.5 * (span - double(scan.aperture));
    out->sensorPose.setYawPitchRoll(out->sensorPose.yaw() + shift, out->sensorPose.pitch(),
                                    out->sensorPose.roll());
    return out;
}

mrpt::obs::CObservation2DRangeScan::Ptr clipRange(const mrpt::obs::CObservation2DRangeScan& scan,
                                                  double range) {
    auto out = std::make_shared<mrpt::obs::CObservation2DRangeScan>(scan);
    out->maxRange = static_cast<float>(std::min<double>(scan.maxRange, range));
    for (std::size_t i = 0; i < out->getScanSize(); ++i) {
        if (out->getScanRange(i) >= range)
            out->setScanRangeValidity(i, false);
    }
    return out;
}

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
    const std::size_t keepEvery = std::max<std::size_t>(1, options.alteration.keepEvery);
    for (std::size_t read = 0;
         (options.maxScans == 0 || read < options.maxScans) && reader.next(record); ++read) {
        if (read % keepEvery != 0) {
            ++summary.scansLeftOut;
            continue;
        }
        if (options.alteration.keepBeamEvery > 1) {
            record.scan = keepEveryBeam(*record.scan, options.alteration.keepBeamEvery);
            record.storedFeatures.reset();
        }
        if (options.alteration.clipRange > 0) {
            record.scan = clipRange(*record.scan, options.alteration.clipRange);
            record.storedFeatures.reset();
        }
        if (options.alteration.mirror) {
            record.scan = mirroredScan(*record.scan);
            record.storedFeatures.reset();
            record.odometry = mirroredPose(record.odometry);
        }
        if (options.alteration.dropOdometry)
            record.hasOdometry = false;
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
    if (summary.scans == 0)
        throw InputError(inputPath, reader.noScansProblem());
    summary.adjustedTimestamps = reader.adjustedTimestamps();
    summary.upsideDownScans = reader.upsideDownScans();
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

std::string describe(const LogConversionSummary& s, const std::string& inputPath,
                     const LogConversionOptions& options) {
    char buf[512];
    std::snprintf(buf, sizeof buf, ": %s, %zu scans of %zu readings, %.3f .. %.3f s (%.1f s)",
                  toString(s.inputFormat), s.scans, s.beamsPerScan, s.firstStamp, s.lastStamp,
                  s.lastStamp - s.firstStamp);
    std::string text = inputPath + buf;
    if (s.adjustedTimestamps > 0)
        text += ", " + std::to_string(s.adjustedTimestamps) + " timestamps repaired";
    if (s.upsideDownScans > 0)
        text += ", " + std::to_string(s.upsideDownScans) + " scans of an upside-down laser";
    if (options.alteration.dropOdometry)
        text += ", odometry left out";
    else if (s.scansWithoutOdometry > 0)
        text += ", " + std::to_string(s.scansWithoutOdometry) + " scans without odometry";
    if (s.scansLeftOut > 0) {
        text += ", " + std::to_string(s.scansLeftOut) + " scans left out (one kept in " +
                std::to_string(options.alteration.keepEvery) + ")";
    }
    if (options.alteration.keepBeamEvery > 1)
        text += ", one beam kept in " + std::to_string(options.alteration.keepBeamEvery);
    if (options.alteration.clipRange > 0) {
        std::snprintf(buf, sizeof buf, ", readings from %.2f m on invalid",
                      options.alteration.clipRange);
        text += buf;
    }
    if (options.alteration.mirror)
        text += ", mirrored (left and right swapped)";
    text += "\n";
    if (!options.rawlogPath.empty()) {
        text += "wrote " + options.rawlogPath + " (" + toString(options.rawlogFormat) +
                " format, " + std::to_string(s.rawlogObjects) + " objects)\n";
    }
    if (!options.odometryTrajectoryPath.empty()) {
        text += "wrote " + options.odometryTrajectoryPath + " (" +
                std::to_string(s.scans - s.scansWithoutOdometry) + " poses)\n";
    }
    return text;
}

}  // namespace toposlam::io
