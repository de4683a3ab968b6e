#pragma once
// Opening an options file for the apps. MRPT's CConfigFile reads anything (random bytes, a
// missing file) without complaint; openIniFile() first checks that the file is there and is
// an .ini file at all, so that options never silently fall back to their defaults:
//  - every line is blank, a comment (# ; //), a [section] or key = value;
//  - no key outside a section, no key twice in a section, no control characters, UTF-8.
// Errors are ConfigError naming the file (and the line).
#include <mrpt/config/CConfigFile.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace toposlam::config {

/// The checked file, read by MRPT (nothing is ever written back to it).
std::unique_ptr<mrpt::config::CConfigFile> openIniFile(const std::string& path);

/// Throws ConfigError unless `config` has [section] (naming the nearest section it has).
void requireSection(const mrpt::config::CConfigFileBase& config, const std::string& section);

/// Throws ConfigError for a section of `config` not in `known` (naming the nearest known one).
void requireKnownSections(const mrpt::config::CConfigFileBase& config,
                          const std::vector<std::string>& known);

/// A number as another library's file has it: its value and its text (for messages: "1e-6",
/// not the "1e-06" the value would print as).
struct WrittenNumber {
    double value = 0;
    std::string text;
};

/// The finite number written for `key` in [section] of a file that another library reads
/// (MRPT reads "abc" as 0 without a word), or nullopt when the key is absent. A comment after
/// the number ("0.8   # share", "80 // iterations") is ignored, as MRPT ignores it: icp-slam's
/// ini files have them. Throws ConfigError naming the file, section, key and text when the
/// text is no finite number.
std::optional<WrittenNumber> readWrittenNumber(const mrpt::config::CConfigFileBase& config,
                                               const std::string& section, const std::string& key);

}  // namespace toposlam::config
