#pragma once
// A laser log (CARMEN or rawlog, any format LaserLogReader reads) converted into an MRPT
// rawlog in either format and/or the odometry trajectory at each scan: what toposlam-convert
// does with logs. All outputs are atomic and written only if the whole log reads cleanly.
#include <toposlam/io/LaserLogReader.h>
#include <toposlam/io/ProgressCallback.h>
#include <toposlam/io/RawlogWriter.h>

#include <cstddef>
#include <string>

namespace toposlam::io {

/// What a conversion changes in the log, each as another robot would have recorded it (the
/// defaults change nothing).
struct LogAlteration {
    /// Keep one scan in this many (the first, then every keepEvery-th): the log as a laser
    /// with a lower scan rate would have recorded it. The odometry is the pose at each kept
    /// scan, so an increment spans the scans left out. 1 = every scan.
    std::size_t keepEvery = 1;
    /// Keep one beam in this many of each scan (the first, then every keepBeamEvery-th): the
    /// log as a laser with that many times the angle between beams would have recorded it.
    /// Each kept beam keeps its direction (the scan's aperture shrinks to the kept beams, and
    /// its sensor yaw turns to their centre if they are no longer centred). Features stored
    /// with the scans are left out (they were found on every beam). 1 = every beam.
    std::size_t keepBeamEvery = 1;
    /// Readings at or beyond this range (m) become invalid, and the scan's maxRange is at most
    /// this: the log as a laser that sees less far would have recorded it. 0 = as recorded.
    double clipRange = 0;
    /// Leave the odometry out: the log as a robot without wheel odometry (a laser-only log)
    /// would have recorded it. Observations format: no CObservationOdometry; sensory frames:
    /// empty action collections.
    bool dropOdometry = false;
    /// The log's mirror image (MirrorImage.h): every scan and the odometry with left and right
    /// swapped, as the robot would have recorded them in the mirror image of its building.
    /// Features stored with the scans are left out.
    bool mirror = false;

    /// Whether any of the above changes the log.
    bool any() const {
        return keepEvery > 1 || keepBeamEvery > 1 || clipRange > 0 || dropOdometry || mirror;
    }
};

struct LogConversionOptions {
    LaserLogOptions read;
    /// Output rawlog ("" = none); gzip-compressed if it ends in ".gz".
    std::string rawlogPath;
    RawlogFormat rawlogFormat = RawlogFormat::Observations;
    /// Output trajectory ("" = none): the odometry at each scan as "fileStamp x y yaw"
    /// (Trajectory.h). The stamps are the scans' fileStamps, so relation files match them.
    /// Scans without odometry are left out.
    std::string odometryTrajectoryPath;
    /// Read only the first this many scans of the input (0 = all).
    std::size_t maxScans = 0;
    /// What to change in the log (as recorded by default).
    LogAlteration alteration;
    /// Called after each scan with (fraction of the input parsed, scans so far).
    ProgressCallback progress;
};

struct LogConversionSummary {
    LaserLogFormat inputFormat = LaserLogFormat::Carmen;
    std::size_t scans = 0;         ///< converted (kept)
    std::size_t scansLeftOut = 0;  ///< read but left out (keepEvery)
    std::size_t scansWithoutOdometry = 0;
    std::size_t beamsPerScan = 0;        ///< of the first scan written (after keepBeamEvery)
    std::size_t adjustedTimestamps = 0;  ///< see LaserLogReader::adjustedTimestamps()
    std::size_t upsideDownScans = 0;     ///< see LaserLogReader::upsideDownScans()
    std::size_t rawlogObjects = 0;
    double firstStamp = 0, lastStamp = 0;  ///< fileStamps, s
};

/// `scan` with one beam in `keepEvery` kept, each in its own direction (LogAlteration::
/// keepBeamEvery). A scan of one beam, or keepEvery <= 1, comes back as a copy.
mrpt::obs::CObservation2DRangeScan::Ptr keepEveryBeam(
    const mrpt::obs::CObservation2DRangeScan& scan, std::size_t keepEvery);

/// `scan` with every reading at or beyond `range` (m) invalid and its maxRange at most `range`
/// (LogAlteration::clipRange).
mrpt::obs::CObservation2DRangeScan::Ptr clipRange(const mrpt::obs::CObservation2DRangeScan& scan,
                                                  double range);

/// Throws InputError for bad input, including a log without any (matching) laser scan, and
/// std::runtime_error when an output cannot be written; no output file is left then.
LogConversionSummary convertLaserLog(const std::string& inputPath,
                                     const LogConversionOptions& options);

/// What a conversion did, for people: "<input>: CARMEN, 5 scans of 181 readings, 9.9 .. 10.2 s
/// (0.3 s), 1 timestamps repaired" (and ", 10 scans left out (one kept in 3)") and a
/// "wrote <file> (...)" line per output, each line ending in a newline.
std::string describe(const LogConversionSummary& summary, const std::string& inputPath,
                     const LogConversionOptions& options);

}  // namespace toposlam::io
