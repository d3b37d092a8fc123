#pragma once
/// \file
/// The threads that think for the computer seats. A search can take a good part of a second;
/// done in the poll loop it would stall every table, so it runs here, on a bounded number of
/// threads (a hall of many computer tables shares them in turn), on a copy of the table's
/// Match: the loop keeps reading its own copy meanwhile, and takes the copy back (with the
/// computer's stream moved on) with the move.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <termpool/match.hpp>
#include <thread>
#include <vector>

#include "hall/unique_fd.hpp"

namespace termpool::hall {

/// A search asked for, or its answer.
struct ComputerJob {
    int table = 0;            ///< the table's number
    std::uint64_t ticket = 0; ///< the table's search ticket when asked (stale answers are dropped)
    Match match; ///< the table's match; the answer's has the computer's stream moved on
    std::optional<ComputerMove> move; ///< the answer: the computer's move
};

/// A fixed set of worker threads, each taking the oldest job; answers wake a poll loop.
class ComputerPool {
public:
    /// Starts `threads` workers (at least one). Check `ok()`.
    explicit ComputerPool(int threads);
    /// Finishes the searches under way, drops those not started, joins every worker.
    ~ComputerPool();
    ComputerPool(const ComputerPool&) = delete;
    ComputerPool& operator=(const ComputerPool&) = delete;

    /// True when the wake pipe could be made.
    bool ok() const { return ok_; }
    /// Queues a search.
    void submit(ComputerJob job);
    /// The answers ready so far (and empties the wake pipe).
    std::vector<ComputerJob> take_answers();
    /// Readable when answers are waiting: for poll(2).
    int wake_fd() const { return wake_.read_end.get(); }

private:
    void work();

    WakePipe wake_;
    bool ok_ = false;
    std::mutex mutex_;
    std::condition_variable ready_;
    std::deque<ComputerJob> jobs_;
    std::vector<ComputerJob> answers_;
    bool stopping_ = false;
    std::vector<std::thread> workers_;
};

} // namespace termpool::hall
