#pragma once
// CARMEN logs (.clf / .log, plain or gzip) as a stream of laser records. The geometry and
// timing rules are documented in LaserLogReader.h; timestamp repair in CarmenTimestamps.h.
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "LineReader.h"
#include "OdometryTrack.h"
#include "ScanSource.h"

namespace toposlam::io {

class CarmenScanSource : public ScanSource {
  public:
    CarmenScanSource(const std::string& path, const LaserLogOptions& options);

    bool next(LaserLogRecord& out) override;
    LaserLogFormat format() const override { return LaserLogFormat::Carmen; }
    double fractionRead() const override { return lines_.fractionRead(); }
    std::string preferredLaser() const override { return preferredLaser_; }

  private:
    void parseFlaser(LaserLogRecord& out, bool front);
    void parseRobotLaser(LaserLogRecord& out);
    void parseRawLaser(LaserLogRecord& out);
    /// Lines that state their beam layout (ROBOTLASER, RAWLASER): checks the field count,
    /// `trailingFields` after the remission values, and returns the index of the first of
    /// them.
    std::size_t statedLayoutEnd(std::size_t trailingFields, const char* layout) const;
    /// The range readings, beam layout and maximum range of such a line, with the laser's
    /// pose on the robot `mount`.
    void parseStatedLayout(mrpt::obs::CObservation2DRangeScan& scan,
                           const mrpt::poses::CPose2D& mount) const;
    void parseParam();
    void checkOdom();
    [[noreturn]] void fail(const std::string& problem) const;
    double number(std::size_t token, const char* what) const;
    std::size_t count(std::size_t token, const char* what) const;
    void expectFields(std::size_t expected, const char* layout) const;
    double param(const std::string& key, double fallback) const;
    void fillRanges(mrpt::obs::CObservation2DRangeScan& scan, std::size_t first, std::size_t n,
                    float maxRange) const;

    std::string path_;
    LaserLogOptions options_;
    LineReader lines_;
    std::vector<double> times_;   // repaired acquisition times of the laser lines, in order
    std::size_t laserLine_ = 0;   // laser lines parsed so far
    std::string preferredLaser_;  // the front laser, found in pass 1
    bool rawLasers_ = false;      // scans from RAWLASER lines, odometry from ODOM lines
    OdometryTrack odometry_;      // a raw log's ODOM lines, at recovered times
    std::map<std::string, double> params_;  // numeric PARAM values, lower-case keys
    std::vector<std::string_view> tokens_;  // fields of the current line (workspace)
};

}  // namespace toposlam::io
