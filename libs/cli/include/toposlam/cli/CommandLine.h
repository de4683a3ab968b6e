#pragma once
// What every TopoSLAM app does with its command line, in one place: TCLAP parsing that reports
// errors as "error: ..." and tells --help apart from a mistake, and parsing of the
// comma-separated number lists that options such as --origin x,y take, and the one-line error
// report when an app fails.
#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace toposlam::cli {

/// Parses the command line. Returns nullopt when the app should go on; otherwise the exit
/// status to return right away: 0 after --help or --version, 1 after a parse error (already
/// printed to stderr as "error: <option>: <problem> (see --help)").
/// (MRPT's bundled TCLAP returns false from parse() for all three instead of throwing.)
std::optional<int> parseCommandLine(TCLAP::CmdLine& cmd, int argc, char** argv);

/// "1.5,-2" -> {1.5, -2}. Throws std::invalid_argument naming `option` unless `text` holds
/// exactly `count` finite numbers.
std::vector<double> parseNumberList(const std::string& text, std::size_t count,
                                    const std::string& option);

/// An app's main(): returns run(argc, argv); an exception escaping it is printed to stderr as
/// "error: <what>" (bad input names its file, see io::InputError) and gives exit status 1.
int runReportingErrors(int (*run)(int, char**), int argc, char** argv);

}  // namespace toposlam::cli
