#pragma once
// Running another program as a child process and measuring what it cost: wall time, CPU time
// and peak resident memory of that process alone (wait4's rusage), so that benchmarks can
// compare programs run one after the other in one session (B3: toposlam-slam vs icp-slam).
#include <cstddef>
#include <string>
#include <vector>

namespace toposlam::evaluation {

struct ChildProcessSpec {
    /// Program and arguments; argv[0] is looked up in PATH when it holds no '/'.
    std::vector<std::string> argv;
    /// Directory the child starts in ("" = the caller's).
    std::string workingDirectory;
    /// Files that receive the child's stdout and stderr (created or truncated; "" =
    /// /dev/null). stdin is always /dev/null: a program waiting for a key press (MRPT apps on
    /// errors) reads end-of-file and goes on.
    std::string stdoutFile;
    std::string stderrFile;
    /// The child is killed (SIGKILL) after this many seconds of wall time; <= 0: no limit.
    double timeoutSeconds = 0;
};

struct ChildProcessResult {
    /// Exit status when the child exited normally, else -1.
    int exitCode = -1;
    /// Signal that ended the child (0 when it exited normally).
    int signal = 0;
    bool timedOut = false;
    /// The program could not be started (not found, not executable): exitCode is 127 and
    /// startError says why (strerror of exec or chdir).
    bool execFailed = false;
    std::string startError;
    double wallSeconds = 0;        ///< from fork to reaping, s
    double userCpuSeconds = 0;     ///< ru_utime of the child, s (all its threads)
    double systemCpuSeconds = 0;   ///< ru_stime, s
    std::size_t peakRssBytes = 0;  ///< ru_maxrss of the child (Linux reports KiB)

    double cpuSeconds() const { return userCpuSeconds + systemCpuSeconds; }
    bool succeeded() const { return exitCode == 0 && !timedOut; }
    /// "exit status 3", "killed by signal 11", "timed out after 60 s", "could not start".
    std::string describeFailure() const;
};

/// Runs the child to completion and returns its status and resource use. Throws
/// std::runtime_error when no process can be created or an output file cannot be opened; a
/// program that cannot be executed is reported in the result (execFailed), not thrown.
ChildProcessResult runChildProcess(const ChildProcessSpec& spec);

/// Runs `argv` in `directory` with its output going to `<directory>/<prefix>stdout.txt` and
/// `<prefix>stderr.txt` (runChildProcess).
ChildProcessResult runChildProcessLogged(const std::vector<std::string>& argv,
                                         const std::string& directory, const std::string& prefix,
                                         double timeoutSeconds);

/// The last non-blank line of a text file (a program's error message in its stderr.txt), at
/// most 300 characters; "" when there is none or the file cannot be read.
std::string lastLineOf(const std::string& file);

/// The path of `program` if it names an executable file (a path with '/') or an executable
/// found in PATH; "" otherwise.
std::string findExecutable(const std::string& program);

}  // namespace toposlam::evaluation
