#pragma once
// A mistake on the command line (a number out of range, options that do not go together): the
// app prints "error: <what>" and exits with status 2, as opposed to 1 for bad input files
// (io::InputError).
#include <stdexcept>
#include <string>

namespace toposlam::cli {

/// Exit status of an app for each kind of outcome (share/doc/apps.md, "Exit status").
enum ExitStatus : int {
    kSuccess = 0,
    kBadInput =
        1,  ///< a missing, unreadable or malformed input file (io::InputError) or any failure
    kBadUsage = 2,  ///< unknown option, missing argument, malformed or out-of-range value
    kNoResult = 3,  ///< the inputs are fine but have no answer (e.g. no path between two rooms)
};

class UsageError : public std::invalid_argument {
  public:
    /// `what`: names the option and the problem, e.g. "--time: must be > 0".
    explicit UsageError(const std::string& what) : std::invalid_argument(what) {}
};

}  // namespace toposlam::cli
