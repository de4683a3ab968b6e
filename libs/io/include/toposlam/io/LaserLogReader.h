#pragma once
// One reader for every laser + odometry log TopoSLAM accepts, yielding a uniform stream of
// (odometry, CObservation2DRangeScan) records:
//  - MRPT rawlogs in both formats (actions/sensory frames, observations only), plain or gz;
//  - CARMEN logs: old FLASER/RLASER (no FOV field), ROBOTLASER1, PARAM; ODOM lines are read but
//    odometry comes from the pose stored in each laser line, as MRPT's importer does.
// Unlike MRPT 2.5.8's own CARMEN import it keeps exact per-scan timestamps, the right aperture
// (180 beams span 180 deg; 360/361 beams span 180 deg), max range / invalid readings and the
// laser's offset from the robot; and a rawlog stream that stops at an unregistered class is an
// error, not a silent truncation.
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace toposlam::io {

enum class LaserLogFormat { RawlogSensoryFrames, RawlogObservations, Carmen };

/// Human-readable name ("rawlog (actions/sensory frames)", "rawlog (observations)", "CARMEN").
const char* toString(LaserLogFormat f);

struct LaserLogOptions {
    /// Keep only scans with this sensor label (empty: every CObservation2DRangeScan).
    std::string scanLabel;
    /// CARMEN: max range (m) when no PARAM line gives one; readings >= it are invalid.
    float carmenDefaultMaxRange = 81.0f;
};

/// One laser scan and the robot's wheel odometry at the same instant.
struct LaserLogRecord {
    /// 0-based position of the scan in the log (file order = processing order).
    std::size_t index = 0;
    /// Timestamp in seconds exactly as the file states it (CARMEN: the ipc_timestamp as
    /// printed, which in old logs can go backwards; rawlog: the MRPT timestamp as Unix seconds).
    /// Ground-truth relation files refer to scans by this value.
    double fileStamp = 0;
    /// The scan. `timestamp` is the exact acquisition time, strictly increasing along the log;
    /// `sensorPose` is the laser pose in the robot frame (m, rad); invalid readings have
    /// validity 0. Never null in a record returned by next().
    mrpt::obs::CObservation2DRangeScan::Ptr scan;
    /// Cumulative odometry of the robot (odometry frame, m, rad) at the scan's time.
    mrpt::poses::CPose2D odometry;
    /// False when the log has no odometry before this scan (odometry is then 0,0,0).
    bool hasOdometry = false;
};

class LaserLogReader {
public:
    /// Opens `path` and detects its format from the content (not the file name).
    /// Throws InputError when the file is missing, unreadable, or of no known format.
    explicit LaserLogReader(const std::string& path, const LaserLogOptions& options = {});
    ~LaserLogReader();
    LaserLogReader(const LaserLogReader&) = delete;
    LaserLogReader& operator=(const LaserLogReader&) = delete;

    /// Reads the next scan into `out`; returns false at the regular end of the log.
    /// Throws InputError (naming the file, and the line or object index) for malformed or
    /// truncated content, wrong CARMEN field counts, NaN or negative ranges, or an object of
    /// a class that is not registered with MRPT.
    bool next(LaserLogRecord& out);

    LaserLogFormat format() const;
    const std::string& path() const;
    /// Fraction of the file consumed so far, in [0,1] (for progress display).
    double fractionRead() const;

    /// Reads the whole log. Throws like next().
    static std::vector<LaserLogRecord> readAll(const std::string& path,
                                               const LaserLogOptions& options = {});

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace toposlam::io
