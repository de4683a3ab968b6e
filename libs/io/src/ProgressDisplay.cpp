#include <toposlam/io/ProgressDisplay.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace toposlam::io {

namespace {

std::string formatDuration(double seconds) {
    const long s = std::max(0L, static_cast<long>(seconds + 0.5));
    char buf[32];
    if (s >= 3600) {
        std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
    } else {
        std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
    }
    return buf;
}

}  // namespace

ProgressDisplay::ProgressDisplay(std::string what, std::string unit)
    : ProgressDisplay(std::move(what), std::move(unit), ::isatty(STDERR_FILENO) == 1) {}

ProgressDisplay::ProgressDisplay(std::string what, std::string unit, bool enabled)
    : what_(std::move(what)),
      unit_(std::move(unit)),
      enabled_(enabled),
      start_(std::chrono::steady_clock::now()),
      lastDraw_(start_) {}

ProgressDisplay::~ProgressDisplay() {
    if (enabled_ && !finished_)
        std::fputc('\n', stderr);
}

void ProgressDisplay::update(double fraction, std::size_t itemsDone) {
    lastItems_ = itemsDone;
    if (!enabled_)
        return;
    const auto now = std::chrono::steady_clock::now();
    if (now - lastDraw_ < std::chrono::milliseconds(100))
        return;
    lastDraw_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    fraction = std::clamp(fraction, 0.0, 1.0);
    const double rate = elapsed > 0 ? static_cast<double>(itemsDone) / elapsed : 0.0;
    const std::string eta =
        fraction > 1e-6 ? formatDuration(elapsed * (1.0 - fraction) / fraction) : "?";
    std::fprintf(stderr, "\r%s: %5.1f%%  %zu %s  %.0f %s/s  ETA %s   ", what_.c_str(),
                 100.0 * fraction, itemsDone, unit_.c_str(), rate, unit_.c_str(), eta.c_str());
    std::fflush(stderr);
}

void ProgressDisplay::finish() {
    if (finished_)
        return;
    finished_ = true;
    if (!enabled_)
        return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double rate = elapsed > 0 ? static_cast<double>(lastItems_) / elapsed : 0.0;
    std::fprintf(stderr, "\r%s: done, %zu %s in %s (%.0f %s/s)            \n", what_.c_str(),
                 lastItems_, unit_.c_str(), formatDuration(elapsed).c_str(), rate, unit_.c_str());
}

}  // namespace toposlam::io
