#pragma once
// What LaserLogReader needs from each log format: records in file order.
#include <toposlam/io/LaserLogReader.h>

#include <string>

namespace toposlam::io {

class ScanSource {
  public:
    virtual ~ScanSource() = default;
    /// Fills `out` (except `index`, which the reader sets) and returns true, or returns false
    /// at the regular end of the log. Throws InputError for bad content.
    virtual bool next(LaserLogRecord& out) = 0;
    virtual LaserLogFormat format() const = 0;
    virtual double fractionRead() const = 0;
    /// The laser to keep when the log has several and only one is wanted (LaserLogOptions::
    /// oneLaser), if the format knows it before the first scan; empty: the first scan's.
    virtual std::string preferredLaser() const { return {}; }
};

}  // namespace toposlam::io
