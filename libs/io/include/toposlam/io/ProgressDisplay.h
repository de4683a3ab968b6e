#pragma once
// One-line progress for long runs on a terminal: fraction done, items per second, ETA.
// Silent when stderr is not a terminal (CI logs, pipes), so logs stay clean.
#include <chrono>
#include <cstddef>
#include <string>

namespace toposlam::io {

class ProgressDisplay {
  public:
    /// `what`: short label ("reading intel.clf"); `unit`: plural item name ("scans").
    /// `enabled`: defaults to whether stderr is a terminal.
    ProgressDisplay(std::string what, std::string unit);
    ProgressDisplay(std::string what, std::string unit, bool enabled);
    ~ProgressDisplay();

    /// `fraction` in [0,1], `itemsDone` since start. Redraws at most ~10 times per second.
    void update(double fraction, std::size_t itemsDone);
    /// Prints the final line (total items, rate, elapsed time) and a newline.
    void finish();

    bool enabled() const { return enabled_; }

  private:
    std::string what_, unit_;
    bool enabled_;
    bool finished_ = false;
    std::size_t lastItems_ = 0;
    std::chrono::steady_clock::time_point start_, lastDraw_;
};

}  // namespace toposlam::io
