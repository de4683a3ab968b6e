#pragma once
// The --keep-every / --keep-beam-every / --clip-range / --no-odometry / --mirror options of the
// apps that can alter a laser log before using it (toposlam-convert writes the altered log,
// toposlam-bench-slam maps it): the log as a laser with a lower scan rate, fewer beams or a
// shorter range, or a robot without wheel odometry, would have recorded it, or the log's
// mirror image (io::LogAlteration). One help text for all of them, with what each app does besides.
#include <toposlam/cli/NumberArg.h>
#include <toposlam/io/LogConversion.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <cstddef>
#include <string>
#include <vector>

namespace toposlam::cli {

class LogAlterationArgs {
  public:
    /// What an app does with each altered log, appended to that option's help (a sentence, or
    /// empty).
    struct Notes {
        std::string keepEvery, keepBeamEvery, clipRange, noOdometry, mirror;
    };

    /// Adds the five options to `cmd`.
    LogAlterationArgs(TCLAP::CmdLine& cmd, const Notes& notes);

    /// The alteration the options ask for (io::LogAlteration::any() is false when none is
    /// given).
    io::LogAlteration alteration() const;
    /// The options given on the command line, as typed ("--keep-every", ...).
    std::vector<std::string> given() const;

  private:
    NumberArg<std::size_t> keepEvery_, keepBeamEvery_;
    NumberArg<double> clipRange_;
    mutable TCLAP::SwitchArg noOdometry_, mirror_;  // MRPT's TCLAP: getValue() is not const
};

}  // namespace toposlam::cli
