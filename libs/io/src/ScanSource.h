#pragma once
// What LaserLogReader needs from each log format: records in file order.
#include <toposlam/io/LaserLogReader.h>

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <string_view>

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

    /// With LaserLogOptions::scanLabel: the scans left out so far for another label, by label.
    const std::map<std::string, std::size_t, std::less<>>& scansOfOtherLabels() const {
        return otherLabels_;
    }

  protected:
    void countOtherLabel(std::string_view label) {
        const auto it = otherLabels_.find(label);
        if (it == otherLabels_.end())
            otherLabels_.emplace(label, 1);
        else
            ++it->second;
    }

  private:
    std::map<std::string, std::size_t, std::less<>> otherLabels_;
};

}  // namespace toposlam::io
