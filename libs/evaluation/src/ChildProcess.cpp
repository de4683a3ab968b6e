#include <toposlam/evaluation/ChildProcess.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace toposlam::evaluation {

namespace {

// A file descriptor closed when it goes out of scope.
class Descriptor {
  public:
    explicit Descriptor(int fd = -1) : fd_(fd) {}
    ~Descriptor() { reset(); }
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    int get() const { return fd_; }
    void reset() {
        if (fd_ >= 0)
            ::close(fd_);
        fd_ = -1;
    }

  private:
    int fd_;
};

int openOrThrow(const std::string& path, int flags) {
    const std::string file = path.empty() ? "/dev/null" : path;
    const int fd = ::open(file.c_str(), flags | O_CLOEXEC, 0644);
    if (fd < 0)
        throw std::runtime_error(file + ": cannot open (" + std::strerror(errno) + ")");
    return fd;
}

double seconds(const timeval& t) {
    return double(t.tv_sec) + 1e-6 * double(t.tv_usec);
}

// Only async-signal-safe calls between fork and exec (the parent may have threads).
[[noreturn]] void execChild(char* const* argv, const char* workingDirectory, int in, int out,
                            int err, int failurePipe) {
    if (::dup2(in, STDIN_FILENO) < 0 || ::dup2(out, STDOUT_FILENO) < 0 ||
        ::dup2(err, STDERR_FILENO) < 0) {
        _exit(127);
    }
    if (workingDirectory[0] != '\0' && ::chdir(workingDirectory) != 0) {
        const int e = errno;
        [[maybe_unused]] const auto n = ::write(failurePipe, &e, sizeof e);
        _exit(127);
    }
    ::execvp(argv[0], argv);
    const int e = errno;
    [[maybe_unused]] const auto n = ::write(failurePipe, &e, sizeof e);
    _exit(127);
}

// Reaps `pid`, killing it once `timeoutSeconds` (> 0) have passed since `start`.
int reap(pid_t pid, double timeoutSeconds, std::chrono::steady_clock::time_point start,
         rusage& usage, bool& timedOut) {
    int status = 0;
    for (;;) {
        const pid_t r = ::wait4(pid, &status, timeoutSeconds > 0 ? WNOHANG : 0, &usage);
        if (r == pid)
            return status;
        if (r < 0 && errno != EINTR)
            throw std::runtime_error(std::string("wait4: ") + std::strerror(errno));
        if (r == 0) {
            const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
            if (elapsed.count() > timeoutSeconds && !timedOut) {
                timedOut = true;
                ::kill(pid, SIGKILL);
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
    }
}

}  // namespace

std::string ChildProcessResult::describeFailure() const {
    std::ostringstream s;
    if (execFailed)
        s << "could not start (" << startError << ")";
    else if (timedOut)
        s << "timed out after " << wallSeconds << " s";
    else if (signal != 0)
        s << "killed by signal " << signal << " (" << ::strsignal(signal) << ")";
    else
        s << "exit status " << exitCode;
    return s.str();
}

ChildProcessResult runChildProcess(const ChildProcessSpec& spec) {
    if (spec.argv.empty())
        throw std::invalid_argument("runChildProcess: no program given");
    std::vector<std::string> args = spec.argv;
    std::vector<char*> argv;
    for (std::string& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);

    const Descriptor in(openOrThrow("", O_RDONLY));
    const Descriptor out(openOrThrow(spec.stdoutFile, O_WRONLY | O_CREAT | O_TRUNC));
    const Descriptor err(openOrThrow(spec.stderrFile, O_WRONLY | O_CREAT | O_TRUNC));
    int pipeFds[2];
    if (::pipe2(pipeFds, O_CLOEXEC) != 0)
        throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    const Descriptor pipeRead(pipeFds[0]);
    Descriptor pipeWrite(pipeFds[1]);

    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid < 0)
        throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
    if (pid == 0) {
        execChild(argv.data(), spec.workingDirectory.c_str(), in.get(), out.get(), err.get(),
                  pipeWrite.get());
    }
    pipeWrite.reset();
    int execErrno = 0;
    ssize_t n;
    do {
        n = ::read(pipeRead.get(), &execErrno, sizeof execErrno);
    } while (n < 0 && errno == EINTR);

    ChildProcessResult result;
    result.execFailed = n == static_cast<ssize_t>(sizeof execErrno);
    if (result.execFailed)
        result.startError = std::strerror(execErrno);
    rusage usage{};
    const int status = reap(pid, spec.timeoutSeconds, start, usage, result.timedOut);
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
    result.wallSeconds = wall.count();
    if (WIFEXITED(status))
        result.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status))
        result.signal = WTERMSIG(status);
    result.userCpuSeconds = seconds(usage.ru_utime);
    result.systemCpuSeconds = seconds(usage.ru_stime);
    result.peakRssBytes = static_cast<std::size_t>(usage.ru_maxrss) * 1024;
    return result;
}

ChildProcessResult runChildProcessLogged(const std::vector<std::string>& argv,
                                         const std::string& directory, const std::string& prefix,
                                         double timeoutSeconds) {
    ChildProcessSpec spec;
    spec.argv = argv;
    spec.workingDirectory = directory;
    spec.stdoutFile = directory + "/" + prefix + "stdout.txt";
    spec.stderrFile = directory + "/" + prefix + "stderr.txt";
    spec.timeoutSeconds = timeoutSeconds;
    return runChildProcess(spec);
}

std::string lastLineOf(const std::string& file) {
    std::ifstream in(file);
    std::string line, last;
    while (std::getline(in, line)) {
        if (line.find_first_not_of(" \t\r") != std::string::npos)
            last = line;
    }
    if (!last.empty() && last.back() == '\r')
        last.pop_back();
    return last.size() > 300 ? last.substr(0, 300) + "..." : last;
}

std::string findExecutable(const std::string& program) {
    const auto executable = [](const std::string& path) {
        struct stat st {};
        return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
               ::access(path.c_str(), X_OK) == 0;
    };
    if (program.empty())
        return "";
    if (program.find('/') != std::string::npos)
        return executable(program) ? program : "";
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/local/bin:/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        const std::string candidate = (dir.empty() ? "." : dir) + "/" + program;
        if (executable(candidate))
            return candidate;
    }
    return "";
}

}  // namespace toposlam::evaluation
