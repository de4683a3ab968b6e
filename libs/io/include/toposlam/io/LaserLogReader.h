#pragma once
// One reader for every laser + odometry log TopoSLAM accepts, yielding a uniform stream of
// (odometry, CObservation2DRangeScan) records in file order:
//  - MRPT rawlogs in both formats (actions/sensory frames, observations only), plain or gz;
//  - CARMEN logs (plain or gz): FLASER/RLASER (old format, no FOV field), ROBOTLASER1/2,
//    PARAM; ODOM lines are checked but odometry comes from the robot pose stored in each
//    laser line, as MRPT's importer and CARMEN's own tools do. Raw logs, whose only laser
//    lines are RAWLASER1/2 (CARMEN's laser module logged without its robot module), take
//    the odometry of the ODOM lines at each scan's time instead (below).
// The format is detected from the content: text is CARMEN, binary is a rawlog.
//
// CARMEN, what MRPT 2.5.8's importer (carmen2rawlog) gets wrong and this reader gets right:
//  - Timestamps: scan->timestamp is the real acquisition time, strictly increasing; stamps
//    that old loggers printed without zero padding are recovered (CarmenTimestamps.h).
//    fileStamp keeps the ipc_timestamp exactly as printed (relation files refer to it).
//    (MRPT gives every scan the same time.)
//  - Beam directions, following CARMEN's readlog.c: old-format lines start at -90 deg with
//    1 deg steps for 180/181 readings, 0.5 deg for 360/361, 0.25 deg for 400/401 (PARAM
//    laser_front_laser_resolution, in degrees, overrides); so 180 readings span -90..+89 deg,
//    360 span -90..+89.5, 361 span -90..+90. Layouts that do not cover ~180 deg are centred.
//    ROBOTLASER lines: reading i points at start_angle + i * angular_resolution.
//    MRPT represents a scan as `aperture` = angle from the first to the last beam,
//    symmetric about the sensor's x axis; an asymmetric layout is represented exactly as
//    aperture = (n-1) * step plus a yaw in sensorPose: for 180 readings aperture = 179 deg
//    and sensor yaw -0.5 deg, so getScanAngle(i) + yaw = -90 + i deg. (MRPT: 90 deg.)
//  - Max range and invalid readings: maximum range from ROBOTLASER's field, else PARAM
//    robot_front_laser_max / robot_rear_laser_max, else LaserLogOptions (81 m: intel's
//    no-return value is 81.83, mit-csail's and fr079's 81.91). A reading >= the maximum range
//    or == 0 is kept with validity 0. A NaN, infinite or negative reading is corrupt input
//    (InputError with the line number), not an invalid beam.
//  - Laser pose on the robot: the laser pose relative to the robot pose stated in the line
//    (FLASER x y theta vs odom_x odom_y odom_theta; ROBOTLASER laser vs robot pose, e.g.
//    0.22 m forward). Where the line states none (both poses equal, as in raw FLASER logs) or
//    an implausible one (> 1 m: a corrected pose estimate, not a mounting offset), PARAM
//    robot_frontlaser_offset / _side_offset / _angular_offset (m, m, rad; rear lasers:
//    robot_rearlaser_*, facing backwards) apply; LaserLogOptions can override it.
//  - RAWLASER1/2 lines (front / rear laser: mount from PARAM) are read only when the log has
//    no FLASER, RLASER or ROBOTLASER line, which carry the odometry synchronised with the
//    scan. Their odometry is the ODOM lines' at the scan's time, both times recovered from
//    their printed stamps, interpolated as in rawlogs' observations format (below): none
//    before the first ODOM line, the last one held after it.
//  - Wrong field counts, non-numeric fields: InputError naming the line.
//
// Upside-down lasers (any format): a scan whose sensorPose turns the laser's z axis to point
// down (roll or pitch of 180 deg, within 5 deg) is returned as the same readings from an
// upright laser, sweeping the other way (rightToLeft flipped, sensorPose level with the yaw
// of the mirrored sweep), so 2D code may read its pose as CPose2D(x, y, yaw). Every reading
// keeps its point in the robot frame. Features stored with such a scan are left out (they
// are in the mirrored frame).
//
// Rawlogs:
//  - Read object by object: a clean end of file ends the stream; a truncated or corrupt
//    object, damaged gzip data, or an object of a class not registered with MRPT (MRPT's
//    readers stop there silently) is an InputError naming the object index (0-based, as
//    RawLogViewer counts) and the class. (A plain, uncompressed rawlog cut exactly between
//    two objects cannot be told from a complete one: the format has no object count; gzip
//    files end with a checksum, so any cut shows.)
//  - Actions/sensory-frame format: odometry is the composition, from (0,0,0), of the
//    CActionRobotMovement2D increments read before the scan (the odometry change of each
//    action; MRPT's own tools integrate them the same way).
//  - Observations format: odometry at the scan's time is interpolated linearly (in the
//    earlier sample's frame) between the bracketing CObservationOdometry samples; at or
//    after the last sample that sample is held; before the first one hasOdometry is false.
//  - fileStamp is the scan's own timestamp (Unix seconds); scan->timestamp is the same,
//    except that non-increasing times are moved 1 us after their predecessor.
//  - Objects of other classes are skipped: camera images, IMU, bearing-range observations,
//    topological maps... provided their class is registered with MRPT in this program
//    (TopoSLAM's apps call toposlam::classes::registerTopoSlamClasses()). Scan features
//    written by toposlam-annotate-features come with their scan (storedFeatures).
//  - Every object is checked before MRPT deserializes it (libs/io/src/MrptObjectCheck.h):
//    lengths against the bytes the file has, versions, nested classes, so corrupt files end
//    with an InputError instead of huge allocations or crashes inside MRPT. Objects of
//    classes the check does not know are first deserialized in a child process with 1 GiB
//    and 5 s (libs/io/src/ObjectDryRun.h).
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace toposlam::features {
class CObservationLaserFeatures;  // libs/features
}  // namespace toposlam::features

namespace toposlam::io {

enum class LaserLogFormat { RawlogSensoryFrames, RawlogObservations, Carmen };

/// Human-readable name ("rawlog (actions/sensory frames)", "rawlog (observations)", "CARMEN").
const char* toString(LaserLogFormat f);

struct LaserLogOptions {
    /// Keep only scans with this sensor label (empty: every CObservation2DRangeScan, or see
    /// oneLaser). CARMEN scans are labelled with their message name: FLASER, RLASER,
    /// ROBOTLASER1, ROBOTLASER2, RAWLASER1, RAWLASER2.
    std::string scanLabel;
    /// With scanLabel empty: when the log holds scans of several lasers, keep those of one
    /// (a SLAM front end registers one sensor's scans against each other): in a CARMEN log
    /// the front laser (FLASER, else ROBOTLASER1, else the first laser line's; in a raw log
    /// RAWLASER1, else RAWLASER2), in a rawlog
    /// the first scan's label. The reader counts the scans it leaves out
    /// (LaserLogReader::otherLaserScans).
    bool oneLaser = false;
    /// CARMEN: max range (m) when no PARAM line gives one; readings >= it are invalid.
    float carmenDefaultMaxRange = 81.0f;
    /// CARMEN: the laser's pose on the robot (x, y in m, phi in rad), replacing whatever the
    /// log states.
    std::optional<mrpt::math::TPose2D> laserPoseOnRobot;
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
    /// False when the log has no odometry for this scan (odometry is then 0,0,0).
    bool hasOdometry = false;
    /// The features stored with this scan in the rawlog, so they need not be extracted
    /// again: a toposlam::features::CObservationLaserFeatures of the same timestamp whose
    /// sensor label begins with the scan's (toposlam-annotate-features writes
    /// "<scan label>_FEATURES" right after each scan, or in the same sensory frame). Null when
    /// the log has none (CARMEN logs never have). The class lives in libs/features, which
    /// builds on this library; read it with laserFeatures().
    mrpt::obs::CObservation::Ptr storedFeatures;

    /// `odometry` as MRPT's map builders take it: a CObservationOdometry labelled "ODOMETRY"
    /// with the scan's timestamp, to be given before the scan. Null when hasOdometry is false.
    mrpt::obs::CObservationOdometry::Ptr odometryObservation() const;

    /// storedFeatures as its class, or null; include
    /// <toposlam/features/CObservationLaserFeatures.h> to call it.
    template <typename Features = features::CObservationLaserFeatures>
    std::shared_ptr<const Features> laserFeatures() const {
        return std::dynamic_pointer_cast<const Features>(storedFeatures);
    }
};

class LaserLogReader {
  public:
    /// Opens `path` and detects its format from the content (not the file name).
    /// Throws InputError when the file is missing, unreadable, empty, or of no known format.
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
    /// Fraction of the log's content parsed so far, in [0,1] (for progress display): it
    /// advances with every scan, whatever the file's buffering or compression.
    double fractionRead() const;
    /// Scans so far whose scan->timestamp differs from their fileStamp by more than 1 us
    /// (recovered CARMEN stamps, times made strictly increasing).
    std::size_t adjustedTimestamps() const;
    /// Scans so far of a laser mounted upside down, read as an upright laser's (see
    /// "Upside-down lasers" above).
    std::size_t upsideDownScans() const;
    /// The label of the scans kept: scanLabel, or with oneLaser the chosen laser's (empty
    /// until the first scan is read, and when every scan is kept).
    const std::string& laserLabel() const;
    /// With oneLaser: the scans left out so far, by sensor label.
    const std::map<std::string, std::size_t>& otherLaserScans() const;
    /// Why the log gave no scan, for an error message once next() returned false at once:
    /// "no laser scans in the log", or with scanLabel "no laser scans labelled 'X' in the log
    /// (it has FLASER: 5000, RLASER: 4998)".
    std::string noScansProblem() const;

    /// Reads the whole log. Throws like next().
    static std::vector<LaserLogRecord> readAll(const std::string& path,
                                               const LaserLogOptions& options = {});

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace toposlam::io
