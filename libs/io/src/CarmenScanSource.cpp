#include "CarmenScanSource.h"

#include <mrpt/core/Clock.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <toposlam/io/CarmenTimestamps.h>
#include <toposlam/io/InputError.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

namespace toposlam::io {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

// A laser pose more than this far from the robot pose in the same line is not a mounting
// offset: the line's "x y theta" is then a corrected pose estimate (as in corrected logs).
constexpr double kMaxMountOffset = 1.0;  // m

void split(std::string_view line, std::vector<std::string_view>& tokens) {
    tokens.clear();
    std::size_t i = 0;
    const std::size_t n = line.size();
    while (i < n) {
        while (i < n && (line[i] == ' ' || line[i] == '\t'))
            ++i;
        if (i >= n)
            break;
        const std::size_t start = i;
        while (i < n && line[i] != ' ' && line[i] != '\t')
            ++i;
        tokens.push_back(line.substr(start, i - start));
    }
}

bool isOldLaser(std::string_view name) {
    return name == "FLASER" || name == "RLASER";
}
bool isRobotLaser(std::string_view name) {
    return name == "ROBOTLASER1" || name == "ROBOTLASER2";
}
// Laser lines that state the robot's pose (and so its odometry).
bool isLaser(std::string_view name) {
    return isOldLaser(name) || isRobotLaser(name);
}
// The laser module's own lines: the scan without a pose. A log is read from them only when
// it has no laser line of the kinds above (CARMEN's raw logs: RAWLASER + ODOM).
bool isRawLaser(std::string_view name) {
    return name == "RAWLASER1" || name == "RAWLASER2";
}

// A field of pass 1, which only collects and leaves the errors to pass 2's line numbers.
bool parsesAs(std::string_view t, double& v) {
    const auto res = std::from_chars(t.data(), t.data() + t.size(), v);
    return res.ec == std::errc() && res.ptr == t.data() + t.size() && std::isfinite(v);
}

bool isCarmenMessage(std::string_view name) {
    return isLaser(name) || name == "ODOM" || name == "PARAM" || name == "SYNC" ||
           name == "TRUEPOS" || name.substr(0, 8) == "RAWLASER";
}

// The ipc_timestamp: third field from the end of every CARMEN message line
// ("... ipc_timestamp ipc_hostname logger_timestamp").
std::string_view printedStamp(const std::vector<std::string_view>& tokens) {
    return tokens.size() >= 4 ? tokens[tokens.size() - 3] : std::string_view();
}

// Beam directions of an old-format FLASER/RLASER line, which states only the number of
// readings. CARMEN's own reader (src/global/readlog.c, carmen_string_to_robot_laser_message_orig
// with carmen_laser_guess_fov / _angle_increment) puts the first beam at -90 deg with a step
// of 1 deg for 180/181 readings, 0.5 deg for 360/361 and 0.25 deg for 400/401 ("last beam
// ignored": 180 readings span -90..+89 deg, 361 span -90..+90). The original GMapping
// CarmenConfiguration does the same (angle = -pi/2, step 1 deg or 0.5 deg). MRPT 2.5.8's
// carmen_log_tools.cpp instead uses aperture = n * 0.5 deg centred on the x axis (90 deg for
// 180 readings). PARAM laser_front_laser_resolution (deg) overrides the step. A layout that
// does not cover ~180 deg (another sensor) is centred on the x axis.
struct BeamLayout {
    double first = 0;  // rad, direction of reading 0 in the laser frame
    double step = 0;   // rad, counter-clockwise
};

BeamLayout oldFormatLayout(std::size_t n, std::optional<double> resolutionDeg) {
    double step = 0;
    if (resolutionDeg) {
        step = *resolutionDeg * kDeg;
    } else if (n == 180 || n == 181) {
        step = 1.0 * kDeg;
    } else if (n == 360 || n == 361) {
        step = 0.5 * kDeg;
    } else if (n == 400 || n == 401) {
        step = 0.25 * kDeg;
    } else {
        step = kPi / static_cast<double>(n - 1);
    }
    const double span = step * static_cast<double>(n - 1);
    return {span >= 179.0 * kDeg - 1e-9 ? -kPi / 2 : -span / 2, step};
}

// PARAM names of the front or rear laser (CARMEN's robot and laser modules).
struct LaserParamNames {
    std::string maxRange, resolution, offset, sideOffset, angularOffset;
};

const LaserParamNames& laserParamNames(bool front) {
    static const LaserParamNames kFront{"robot_front_laser_max", "laser_front_laser_resolution",
                                        "robot_frontlaser_offset", "robot_frontlaser_side_offset",
                                        "robot_frontlaser_angular_offset"};
    static const LaserParamNames kRear{"robot_rear_laser_max", "laser_rear_laser_resolution",
                                       "robot_rearlaser_offset", "robot_rearlaser_side_offset",
                                       "robot_rearlaser_angular_offset"};
    return front ? kFront : kRear;
}

// The laser's pose on the robot (m, rad): the one the line states (laser pose relative to
// the robot pose), or, when the line states none (both poses equal, as in raw FLASER logs),
// the PARAM offsets robot_{front,rear}laser_{offset,side_offset,angular_offset} (rear lasers
// face backwards, as in GMapping's CarmenConfiguration), or the user's override.
mrpt::poses::CPose2D laserMount(const mrpt::poses::CPose2D& laser,
                                const mrpt::poses::CPose2D& robot, bool front,
                                const std::map<std::string, double>& params,
                                const LaserLogOptions& options) {
    if (options.laserPoseOnRobot)
        return mrpt::poses::CPose2D(*options.laserPoseOnRobot);
    const mrpt::poses::CPose2D stated = laser - robot;
    const bool none =
        std::abs(stated.x()) < 1e-9 && std::abs(stated.y()) < 1e-9 && std::abs(stated.phi()) < 1e-9;
    if (!none && std::hypot(stated.x(), stated.y()) <= kMaxMountOffset)
        return stated;
    const LaserParamNames& names = laserParamNames(front);
    const auto get = [&](const std::string& key) {
        const auto it = params.find(key);
        return it == params.end() ? 0.0 : it->second;
    };
    return mrpt::poses::CPose2D(get(names.offset), get(names.sideOffset),
                                get(names.angularOffset) + (front ? 0.0 : kPi));
}

// A pose exactly as the log prints it: CPose2D's constructor wraps the angle with arithmetic
// that changes its last bits even when it is already in (-pi, pi].
mrpt::poses::CPose2D printedPose(double x, double y, double theta) {
    mrpt::poses::CPose2D pose(x, y, theta);
    if (theta > -kPi && theta <= kPi)
        pose.phi(theta);
    return pose;
}

}  // namespace

CarmenScanSource::CarmenScanSource(const std::string& path, const LaserLogOptions& options)
    : path_(path), options_(options), lines_(path) {
    // Pass 1: the printed stamps of all laser lines, to recover real acquisition times
    // (CarmenTimestamps.h) before the scans are parsed one by one in pass 2; and, until a
    // laser line that states the robot's pose shows up, the ODOM lines, which raw logs need.
    LineReader pass1(path);
    std::vector<std::string> printed, rawPrinted, odometryPrinted;
    std::vector<mrpt::poses::CPose2D> odometryPoses;
    std::size_t messages = 0;
    bool flaser = false, robotLaser1 = false, rawLaser1 = false;
    std::string_view line;
    while (pass1.next(line)) {
        split(line, tokens_);
        if (tokens_.empty())
            continue;
        if (isCarmenMessage(tokens_[0]))
            ++messages;
        if (isLaser(tokens_[0])) {
            printed.emplace_back(printedStamp(tokens_));
            if (preferredLaser_.empty())
                preferredLaser_ = std::string(tokens_[0]);
            flaser = flaser || tokens_[0] == "FLASER";
            robotLaser1 = robotLaser1 || tokens_[0] == "ROBOTLASER1";
        } else if (printed.empty() && isRawLaser(tokens_[0])) {
            rawPrinted.emplace_back(printedStamp(tokens_));
            rawLaser1 = rawLaser1 || tokens_[0] == "RAWLASER1";
        } else if (printed.empty() && tokens_[0] == "ODOM" && tokens_.size() == 10) {
            double x = 0, y = 0, theta = 0;
            if (parsesAs(tokens_[1], x) && parsesAs(tokens_[2], y) && parsesAs(tokens_[3], theta)) {
                odometryPrinted.emplace_back(printedStamp(tokens_));
                odometryPoses.push_back(printedPose(x, y, theta));
            }
        }
    }
    // The front laser: the one the robot looks ahead with.
    if (flaser)
        preferredLaser_ = "FLASER";
    else if (robotLaser1)
        preferredLaser_ = "ROBOTLASER1";
    if (const std::string damage = pass1.streamError(); !damage.empty()) {
        throw InputError(path, "truncated or corrupt gzip data (" + damage + ")");
    }
    lines_.setDecompressedSize(pass1.bytesParsed());  // exact, for a smooth progress fraction
    if (messages == 0) {
        throw InputError(path,
                         "not a CARMEN log: no FLASER, RLASER, ROBOTLASER1, RAWLASER1, ODOM or "
                         "PARAM line (and not an MRPT rawlog either)");
    }
    if (printed.empty() && !rawPrinted.empty()) {
        // A raw log: the scans' odometry is read off the ODOM lines at the scans' times,
        // both recovered the same way from their printed stamps.
        rawLasers_ = true;
        preferredLaser_ = rawLaser1 ? "RAWLASER1" : "RAWLASER2";
        printed = std::move(rawPrinted);
        const std::vector<std::string_view> stamps(odometryPrinted.begin(), odometryPrinted.end());
        const std::vector<double> times = repairCarmenTimestamps(stamps).times;
        for (std::size_t i = 0; i < times.size(); ++i)
            odometry_.add(times[i], odometryPoses[i]);
    }
    const std::vector<std::string_view> views(printed.begin(), printed.end());
    times_ = repairCarmenTimestamps(views).times;
}

void CarmenScanSource::fail(const std::string& problem) const {
    throw InputError(path_, "line " + std::to_string(lines_.lineNumber()) + ": " + problem);
}

double CarmenScanSource::number(std::size_t token, const char* what) const {
    const std::string_view t = tokens_[token];
    double v = 0;
    const auto res = std::from_chars(t.data(), t.data() + t.size(), v);
    if (res.ec != std::errc() || res.ptr != t.data() + t.size()) {
        fail(std::string(what) + " is not a number: '" + std::string(t) + "'");
    }
    if (!std::isfinite(v))
        fail(std::string(what) + " is " + std::string(t));
    return v;
}

std::size_t CarmenScanSource::count(std::size_t token, const char* what) const {
    if (token >= tokens_.size())
        fail(std::string("line ends before the ") + what);
    const std::string_view t = tokens_[token];
    std::size_t v = 0;
    const auto res = std::from_chars(t.data(), t.data() + t.size(), v);
    if (res.ec != std::errc() || res.ptr != t.data() + t.size()) {
        fail(std::string(what) + " is not a count: '" + std::string(t) + "'");
    }
    // A count of fields that follow cannot exceed the fields the line has; checking it here
    // also keeps the field arithmetic of the callers (n + 11, ...) from overflowing.
    if (v > tokens_.size()) {
        fail(std::string(what) + " is " + std::string(t) + " but the line has only " +
             std::to_string(tokens_.size()) + " fields");
    }
    return v;
}

void CarmenScanSource::expectFields(std::size_t expected, const char* layout) const {
    if (tokens_.size() != expected) {
        fail(std::string(tokens_[0]) + " has " + std::to_string(tokens_.size()) +
             " fields, expected " + std::to_string(expected) + " (" + layout + ")");
    }
}

double CarmenScanSource::param(const std::string& key, double fallback) const {
    const auto it = params_.find(key);
    return it == params_.end() ? fallback : it->second;
}

void CarmenScanSource::fillRanges(mrpt::obs::CObservation2DRangeScan& scan, std::size_t first,
                                  std::size_t n, float maxRange) const {
    scan.resizeScan(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::string_view t = tokens_[first + i];
        float r = 0;
        const auto res = std::from_chars(t.data(), t.data() + t.size(), r);
        if (res.ec != std::errc() || res.ptr != t.data() + t.size()) {
            fail("reading " + std::to_string(i) + " is not a number: '" + std::string(t) + "'");
        }
        // A NaN or negative distance is corrupt data, not an absent return (those are 0 or
        // >= the maximum range in CARMEN logs): reject the file rather than guess.
        if (!std::isfinite(r))
            fail("reading " + std::to_string(i) + " is " + std::string(t));
        if (r < 0)
            fail("reading " + std::to_string(i) + " is negative (" + std::string(t) + ")");
        scan.setScanRange(i, r);
        scan.setScanRangeValidity(i, r > 0 && r < maxRange);
    }
}

void CarmenScanSource::parseFlaser(LaserLogRecord& out, bool front) {
    const std::size_t n = count(1, "number of readings");
    if (n < 2)
        fail("a scan needs at least 2 readings");
    expectFields(n + 11,
                 "FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_timestamp "
                 "ipc_hostname logger_timestamp");
    const LaserParamNames& names = laserParamNames(front);
    const auto maxRange = static_cast<float>(param(names.maxRange, options_.carmenDefaultMaxRange));
    std::optional<double> resolution;
    if (const auto it = params_.find(names.resolution); it != params_.end()) {
        resolution = it->second;
    }
    const BeamLayout layout = oldFormatLayout(n, resolution);

    const std::size_t p = 2 + n;
    const auto laser = printedPose(number(p, "x"), number(p + 1, "y"), number(p + 2, "theta"));
    const auto robot =
        printedPose(number(p + 3, "odom_x"), number(p + 4, "odom_y"), number(p + 5, "odom_theta"));
    auto scan = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
    scan->sensorLabel = std::string(tokens_[0]);
    fillRanges(*scan, 2, n, maxRange);
    const double span = layout.step * static_cast<double>(n - 1);
    const auto mount = laserMount(laser, robot, front, params_, options_);
    scan->aperture = static_cast<float>(span);
    scan->rightToLeft = true;
    scan->maxRange = maxRange;
    scan->sensorPose = mrpt::poses::CPose3D(mount.x(), mount.y(), 0.0,
                                            mount.phi() + layout.first + span / 2, 0.0, 0.0);
    out.fileStamp = number(p + 6, "ipc_timestamp");
    out.odometry = robot;
    out.hasOdometry = true;
    out.scan = std::move(scan);
}

std::size_t CarmenScanSource::statedLayoutEnd(std::size_t trailingFields,
                                              const char* layout) const {
    // "name laser_type start_angle fov angular_resolution maximum_range accuracy
    // remission_mode n r1..rn m v1..vm": the same first fields in ROBOTLASER and RAWLASER.
    const std::size_t n = count(8, "number of readings");
    if (n < 2)
        fail("a scan needs at least 2 readings");
    const std::size_t m = count(9 + n, "number of remission values");
    expectFields(10 + n + m + trailingFields, layout);
    return 10 + n + m;
}

void CarmenScanSource::parseStatedLayout(mrpt::obs::CObservation2DRangeScan& scan,
                                         const mrpt::poses::CPose2D& mount) const {
    const std::size_t n = count(8, "number of readings");
    const double start = number(2, "start_angle");
    const double step = number(4, "angular_resolution");
    const double maxRange = number(5, "maximum_range");
    if (!(step > 0))
        fail("angular_resolution must be > 0");
    if (!(maxRange > 0))
        fail("maximum_range must be > 0");
    scan.sensorLabel = std::string(tokens_[0]);
    fillRanges(scan, 9, n, static_cast<float>(maxRange));
    // Reading i points at start_angle + i * angular_resolution (CARMEN's definition).
    const double span = step * static_cast<double>(n - 1);
    scan.aperture = static_cast<float>(span);
    scan.rightToLeft = true;
    scan.maxRange = static_cast<float>(maxRange);
    scan.sensorPose =
        mrpt::poses::CPose3D(mount.x(), mount.y(), 0.0, mount.phi() + start + span / 2, 0.0, 0.0);
}

void CarmenScanSource::parseRobotLaser(LaserLogRecord& out) {
    const std::size_t p = statedLayoutEnd(14,
                                          "ROBOTLASER1 laser_type start_angle fov "
                                          "angular_resolution maximum_range accuracy "
                                          "remission_mode n r1..rn m v1..vm laser_x laser_y "
                                          "laser_theta robot_x robot_y robot_theta tv rv "
                                          "forward_safety_dist side_safety_dist turn_axis "
                                          "ipc_timestamp ipc_hostname logger_timestamp");
    const auto laser =
        printedPose(number(p, "laser_x"), number(p + 1, "laser_y"), number(p + 2, "laser_theta"));
    const auto robot = printedPose(number(p + 3, "robot_x"), number(p + 4, "robot_y"),
                                   number(p + 5, "robot_theta"));
    auto scan = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
    parseStatedLayout(*scan,
                      laserMount(laser, robot, tokens_[0] == "ROBOTLASER1", params_, options_));
    out.fileStamp = number(p + 11, "ipc_timestamp");
    out.odometry = robot;
    out.hasOdometry = true;
    out.scan = std::move(scan);
}

void CarmenScanSource::parseRawLaser(LaserLogRecord& out) {
    const std::size_t p = statedLayoutEnd(3,
                                          "RAWLASER1 laser_type start_angle fov "
                                          "angular_resolution maximum_range accuracy "
                                          "remission_mode n r1..rn m v1..vm ipc_timestamp "
                                          "ipc_hostname logger_timestamp");
    // The line states no pose: the mount is PARAM's (or the user's), the odometry the ODOM
    // lines' at the scan's time (next()).
    const mrpt::poses::CPose2D none;
    auto scan = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
    parseStatedLayout(*scan, laserMount(none, none, tokens_[0] == "RAWLASER1", params_, options_));
    out.fileStamp = number(p, "ipc_timestamp");
    out.scan = std::move(scan);
}

void CarmenScanSource::parseParam() {
    // PARAM name value [ipc_hostname logger_timestamp]; only numeric values matter here.
    if (tokens_.size() < 3)
        fail("PARAM needs a name and a value");
    std::string key(tokens_[1]);
    for (char& c : key)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    double v = 0;
    const auto t = tokens_[2];
    const auto res = std::from_chars(t.data(), t.data() + t.size(), v);
    if (res.ec == std::errc() && res.ptr == t.data() + t.size() && std::isfinite(v)) {
        params_[key] = v;
    }
}

void CarmenScanSource::checkOdom() {
    // Odometry comes from the laser lines, or in a raw log from pass 1's copy of these lines;
    // here they are checked for corruption.
    expectFields(10, "ODOM x y theta tv rv accel ipc_timestamp ipc_hostname logger_timestamp");
    number(1, "x");
    number(2, "y");
    number(3, "theta");
}

bool CarmenScanSource::next(LaserLogRecord& out) {
    std::string_view line;
    while (lines_.next(line)) {
        split(line, tokens_);
        if (tokens_.empty() || tokens_[0].front() == '#')
            continue;
        const std::string_view name = tokens_[0];
        if (rawLasers_ ? isRawLaser(name) : isLaser(name)) {
            const std::size_t laserIndex = laserLine_++;
            if (!options_.scanLabel.empty() && name != options_.scanLabel) {
                countOtherLabel(name);
                continue;
            }
            if (isOldLaser(name)) {
                parseFlaser(out, name == "FLASER");
            } else if (isRobotLaser(name)) {
                parseRobotLaser(out);
            } else {
                parseRawLaser(out);
            }
            const double time = laserIndex < times_.size() ? times_[laserIndex] : out.fileStamp;
            out.scan->timestamp = mrpt::Clock::fromDouble(time);
            if (rawLasers_) {
                const std::optional<mrpt::poses::CPose2D> odometry = odometry_.at(time);
                out.hasOdometry = odometry.has_value();
                out.odometry = odometry.value_or(mrpt::poses::CPose2D());
            }
            return true;
        }
        if (name == "PARAM") {
            parseParam();
        } else if (name == "ODOM") {
            checkOdom();
        }
    }
    if (const std::string damage = lines_.streamError(); !damage.empty()) {
        throw InputError(path_, "truncated or corrupt gzip data (" + damage + ")");
    }
    return false;
}

}  // namespace toposlam::io
