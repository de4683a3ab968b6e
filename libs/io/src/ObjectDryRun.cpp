#include "ObjectDryRun.h"

#include <fcntl.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>

#include "MrptErrorText.h"

// In sanitizer builds (tests, fuzzing): the callback that reports a dying process, which the
// child must not run (libFuzzer's saves the input as a crash of the parent).
extern "C" __attribute__((weak)) void __sanitizer_set_death_callback(void (*callback)(void));

namespace toposlam::io {

namespace {

enum class Outcome : uint8_t { Read, NeedMoreBytes, Failed };

struct Report {
    Outcome outcome = Outcome::Failed;
    uint64_t size = 0;
    char message[400] = {};
};

uint64_t addressSpaceInUse() {
    unsigned long pages = 0;
    if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%lu", &pages) != 1)
            pages = 0;
        std::fclose(f);
    }
    return static_cast<uint64_t>(pages) * static_cast<uint64_t>(::sysconf(_SC_PAGESIZE));
}

// The child: its own memory limit and default crash behaviour, one ReadObject, a report.
[[noreturn]] void dryRunInChild(const unsigned char* bytes, std::size_t available, int out) {
    if (__sanitizer_set_death_callback)
        __sanitizer_set_death_callback(nullptr);
    for (int sig : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL})
        std::signal(sig, SIG_DFL);
    const rlimit limit{addressSpaceInUse() + kDryRunMemoryBytes,
                       addressSpaceInUse() + kDryRunMemoryBytes};
    ::setrlimit(RLIMIT_AS, &limit);
    Report report;
    mrpt::io::CMemoryStream memory;
    memory.assignMemoryNotOwn(bytes, available);
    try {
        auto archive = mrpt::serialization::archiveFrom(memory);
        archive.ReadObject();
        report.outcome = Outcome::Read;
        report.size = memory.getPosition();
    } catch (const std::bad_alloc&) {
        std::snprintf(report.message, sizeof report.message,
                      "reading it needs more than %zu MiB of memory", kDryRunMemoryBytes >> 20);
    } catch (const std::exception& e) {
        report.outcome =
            memory.getPosition() >= available ? Outcome::NeedMoreBytes : Outcome::Failed;
        std::snprintf(report.message, sizeof report.message, "%s", mrptErrorSummary(e).c_str());
    }
    [[maybe_unused]] const auto written = ::write(out, &report, sizeof report);
    ::_exit(0);
}

// Waits for the child's report, at most kDryRunSeconds; kills it after that.
Report collectReport(pid_t child, int in) {
    Report report;
    std::size_t got = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kDryRunSeconds);
    bool timedOut = false;
    while (got < sizeof report) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                              deadline - std::chrono::steady_clock::now())
                              .count();
        pollfd p{in, POLLIN, 0};
        const int ready = left > 0 ? ::poll(&p, 1, static_cast<int>(left)) : 0;
        if (ready < 0 && errno == EINTR)
            continue;
        if (ready <= 0) {
            timedOut = ready == 0;
            break;
        }
        const ssize_t n = ::read(in, reinterpret_cast<char*>(&report) + got, sizeof report - got);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        got += static_cast<std::size_t>(n);
    }
    if (got < sizeof report)
        ::kill(child, SIGKILL);
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    if (got == sizeof report)
        return report;
    report = Report{};
    if (timedOut) {
        std::snprintf(report.message, sizeof report.message, "reading it took longer than %d s",
                      kDryRunSeconds);
    } else {
        std::snprintf(report.message, sizeof report.message,
                      "reading it crashed or exceeded %zu MiB of memory (%s)",
                      kDryRunMemoryBytes >> 20,
                      WIFSIGNALED(status) ? strsignal(WTERMSIG(status)) : "no report");
    }
    return report;
}

Report dryRunInChildProcess(const unsigned char* bytes, std::size_t available) {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
        return {Outcome::Failed, 0, "cannot create a pipe for the dry run"};
    const pid_t child = ::fork();
    if (child == 0) {
        ::close(fds[0]);
        dryRunInChild(bytes, available, fds[1]);
    }
    ::close(fds[1]);
    Report report;
    if (child < 0) {
        std::snprintf(report.message, sizeof report.message, "cannot start the dry run (%s)",
                      std::strerror(errno));
    } else {
        report = collectReport(child, fds[0]);
    }
    ::close(fds[0]);
    report.message[sizeof report.message - 1] = '\0';
    return report;
}

}  // namespace

DryRunResult dryRunNextObject(LookaheadStream& in) {
    // Start with 1 MiB ahead; an object that needs more is tried again with 4 times as much,
    // until the whole rest of the file is buffered.
    std::size_t window = std::size_t{1} << 20;
    while (true) {
        const bool wholeRest = !in.ensure(window);
        const Report report = dryRunInChildProcess(in.ahead(), in.buffered());
        if (report.outcome == Outcome::Read)
            return {true, static_cast<std::size_t>(report.size), {}};
        if (report.outcome == Outcome::NeedMoreBytes && !wholeRest) {
            window *= 4;
            continue;
        }
        return {false, 0,
                report.outcome == Outcome::NeedMoreBytes
                    ? "the file ends inside it (" + std::string(report.message) + ")"
                    : std::string(report.message)};
    }
}

}  // namespace toposlam::io
