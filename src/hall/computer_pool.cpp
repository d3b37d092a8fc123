#include "hall/computer_pool.hpp"

#include <algorithm>

namespace termpool::hall {

ComputerPool::ComputerPool(int threads) {
    ok_ = wake_.open();
    for (int i = 0; i < std::max(1, threads); ++i)
        workers_.emplace_back([this] { work(); });
}

ComputerPool::~ComputerPool() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
        jobs_.clear();
    }
    ready_.notify_all();
    for (std::thread& worker : workers_)
        worker.join();
}

void ComputerPool::submit(ComputerJob job) {
    {
        const std::lock_guard lock(mutex_);
        jobs_.push_back(std::move(job));
    }
    ready_.notify_one();
}

std::vector<ComputerJob> ComputerPool::take_answers() {
    wake_.drain();
    const std::lock_guard lock(mutex_);
    return std::exchange(answers_, {});
}

void ComputerPool::work() {
    for (;;) {
        std::unique_lock lock(mutex_);
        ready_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
        if (stopping_)
            return;
        ComputerJob job = std::move(jobs_.front());
        jobs_.pop_front();
        lock.unlock();

        job.move = job.match.computer_move();

        lock.lock();
        answers_.push_back(std::move(job));
        lock.unlock();
        wake_.wake();
    }
}

} // namespace termpool::hall
