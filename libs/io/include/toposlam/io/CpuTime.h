#pragma once
// CPU time of the calling thread: what timings of one stage report, so that other processes
// on a busy machine do not inflate them (wall time is reported beside it where it matters).
#include <ctime>

namespace toposlam::io {

/// Seconds of CPU time the calling thread has used.
inline double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// Seconds of CPU time the whole process (all its threads) has used.
inline double processCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace toposlam::io
