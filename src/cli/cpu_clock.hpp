#pragma once
// CPU clocks for the commands' figures: on a shared machine wall time moves with the load
// (up to 7 times between runs), the CPU time a thread or the process used much less.

#include <ctime>

namespace termpool::cli {

/// CPU time of clock `id` (CLOCK_THREAD_CPUTIME_ID, CLOCK_PROCESS_CPUTIME_ID), s.
inline double cpu_seconds(clockid_t id) {
    timespec t{};
    clock_gettime(id, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// CPU time of the calling thread, s: its work on one core, whatever else the machine runs.
inline double thread_cpu_seconds() {
    return cpu_seconds(CLOCK_THREAD_CPUTIME_ID);
}

/// CPU time of all the process's threads, s.
inline double process_cpu_seconds() {
    return cpu_seconds(CLOCK_PROCESS_CPUTIME_ID);
}

} // namespace termpool::cli
