#pragma once
// What every TopoSLAM app does with its command line, in one place: TCLAP parsing that reports
// errors as "error: ..." and tells --help apart from a mistake, parsing of the comma-separated
// number lists that options such as --origin x,y take, and the one-line error report and exit
// status when an app fails. Numeric options: NumberArg.h.
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <toposlam/cli/NumberRange.h>
#include <toposlam/cli/UsageError.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace toposlam::cli {

/// Parses the command line. Returns nullopt when the app should go on; otherwise the exit
/// status to return right away: 0 after --help or --version, 2 (kBadUsage) after a parse error
/// (already printed to stderr as "error: <option>: <problem> (see --help)").
/// (MRPT's bundled TCLAP returns false from parse() for all three instead of throwing.)
std::optional<int> parseCommandLine(TCLAP::CmdLine& cmd, int argc, char** argv);

/// "1.5,-2" -> {1.5, -2}. Throws UsageError naming `option` unless `text` holds exactly `count`
/// numbers, each in `range` (default: finite and within +-1e6, e.g. metres or degrees).
std::vector<double> parseNumberList(
    const std::string& text, std::size_t count, const std::string& option,
    const NumberRange<double>& range = NumberRange<double>::closed(-1e6, 1e6));

/// Takes "<flag> <value>" out of argv (the first such pair; argc shrinks by two) and returns
/// the value, or `fallback` when the flag is not there: an app's own option, before the rest of
/// the command line goes to a parser of its own (Google Benchmark's).
std::string takeOption(int& argc, char** argv, const std::string& flag, std::string fallback);

/// "a,b,,c" -> {"a", "b", "c"}: the items of a comma-separated list option, empty ones left out.
std::vector<std::string> splitList(const std::string& text);

/// "1-3,7" -> {1, 2, 3, 7}: seeds and ranges of seeds. Throws UsageError naming `option` unless
/// every item is a whole number >= 0 (at most 1e9) or a range of two.
std::vector<unsigned> parseSeedList(const std::string& text, const std::string& option);

/// A file named on the command line: the option that named it ("" for a positional argument)
/// and its path ("": not given). `via`: for a file an app reads or writes along with one named
/// on the command line (a map's .yaml sidecar, a file in an output folder), what it is to that
/// one ("the sidecar of 'a.png'"), said in messages after its path.
struct FileArgument {
    std::string option, path;
    std::string via = {};
};
/// Throws UsageError unless every output given is a file of its own: not one of the inputs
/// (toposlam-convert a.clf -o a.clf replaced the log with its conversion) and not another
/// output (one would silently replace the other). Paths are compared as the files they name:
/// "a.clf", "./a.clf" and a link to it are one file.
void requireOutputsOfTheirOwn(const std::vector<FileArgument>& inputs,
                              const std::vector<FileArgument>& outputs);

/// `map` and every file read with it (a picture's .yaml sidecar, the picture a .yaml names):
/// the inputs to check outputs against (io::gridMapFilesRead).
std::vector<FileArgument> mapFilesRead(const FileArgument& map);
/// `map` and every file written with it (the ROS pair of a .png, .yaml or .pgm output).
std::vector<FileArgument> mapFilesWritten(const FileArgument& map);
/// The files `names` an app writes in its output folder `folder`.
std::vector<FileArgument> filesInFolder(const FileArgument& folder,
                                        const std::vector<std::string>& names);

/// Throws UsageError unless `file` (when given) ends with one of `extensions` (".png",
/// ".rawlog.gz"; case-insensitive): a rawlog written as "map.png", or a plot as "p.txt",
/// fails late or is no file of the kind its name says.
void requireExtension(const FileArgument& file, const std::vector<std::string>& extensions);

/// Throws, before an app does its work, unless the output folder `folder` names can be made
/// and written: it, or the nearest of its parents that exists, is a folder the app may create
/// files in (std::runtime_error "<folder>: cannot create the output folder (...)": exit 1; an
/// empty path is a UsageError). Nothing is created, so a run that fails later leaves nothing.
void requireWritableOutputFolder(const FileArgument& folder);

/// Throws, before an app does its work, unless every output file given can be written: its
/// folder exists and the app may create files in it, and it is no folder itself
/// (std::runtime_error "<file>: cannot write the file (...)": exit 1). Nothing is created.
void requireWritableOutputFiles(const std::vector<FileArgument>& files);

/// An app's main(): returns run(argc, argv). An exception escaping it is printed to stderr as
/// "error: <what>" and gives the exit status: 2 for a UsageError (bad command line), 1 for
/// anything else (bad input names its file, see io::InputError).
int runReportingErrors(int (*run)(int, char**), int argc, char** argv);

}  // namespace toposlam::cli
