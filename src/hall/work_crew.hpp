#pragma once
/// \file
/// A few threads that run a batch of independent jobs together and return when all are done.
/// The hall's loop saves the tables that took an action in one round this way: each save
/// waits for the disk (two fsyncs), and saves made side by side share the disk's time rather
/// than queue one behind the other on the loop's thread.

#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace termpool::hall {

/// A fixed set of helper threads; `run` hands them a batch and works on it too.
class WorkCrew {
public:
    /// Starts `helpers` threads (none: `run` does every job itself). They start with the
    /// caller's signal mask.
    explicit WorkCrew(int helpers);
    /// Joins the helpers (no batch may be running).
    ~WorkCrew();
    WorkCrew(const WorkCrew&) = delete;
    WorkCrew& operator=(const WorkCrew&) = delete;

    /// Calls `job(i)` for every i below `count`, spread over the helpers and this thread, and
    /// returns once every call has returned. The jobs must not depend on each other's order.
    /// One batch at a time: `run` is called from one thread.
    void run(std::size_t count, const std::function<void(std::size_t)>& job);

private:
    // Runs jobs of the current batch while some are left; the lock is held on entry and exit.
    void take_jobs(std::unique_lock<std::mutex>& lock);
    void help();

    std::mutex mutex_;
    std::condition_variable work_;     // a batch has jobs left, or stopping
    std::condition_variable finished_; // the batch's last job returned
    const std::function<void(std::size_t)>* job_ = nullptr;
    std::size_t count_ = 0;
    std::size_t next_ = 0; // the next job to start
    std::size_t done_ = 0; // jobs returned
    bool stopping_ = false;
    std::vector<std::thread> helpers_;
};

} // namespace termpool::hall
