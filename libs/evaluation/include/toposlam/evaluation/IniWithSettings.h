#pragma once
// A copy of an .ini file with a few keys set, so that a benchmark can run a program with its
// usual configuration and one change (B3: toposlam-slam's config with `[Slam] engine = icp`;
// icp-slam's config with its output folder moved) without touching the original.
#include <string>
#include <vector>

namespace toposlam::evaluation {

struct IniSetting {
    std::string section;
    std::string key;
    std::string value;
};

/// Reads `source` with MRPT's .ini parser, sets every setting (adding the key, or replacing
/// the value `source` gives it) and writes the result to `destination` atomically. Comments
/// are not kept. Throws io::InputError when `source` cannot be read, std::runtime_error when
/// `destination` cannot be written.
void writeIniWithSettings(const std::string& source, const std::string& destination,
                          const std::vector<IniSetting>& settings);

/// The value of `section`/`key` in the .ini file `path`, or `fallback` when absent. Throws
/// io::InputError when the file cannot be read.
double readIniNumber(const std::string& path, const std::string& section, const std::string& key,
                     double fallback);

}  // namespace toposlam::evaluation
