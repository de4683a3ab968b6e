#pragma once
// What LaserLogReader needs from each log format: records in file order.
#include <toposlam/io/LaserLogReader.h>

namespace toposlam::io {

class ScanSource {
  public:
    virtual ~ScanSource() = default;
    /// Fills `out` (except `index`, which the reader sets) and returns true, or returns false
    /// at the regular end of the log. Throws InputError for bad content.
    virtual bool next(LaserLogRecord& out) = 0;
    virtual LaserLogFormat format() const = 0;
    virtual double fractionRead() const = 0;
};

}  // namespace toposlam::io
