#include "hall/work_crew.hpp"

namespace termpool::hall {

WorkCrew::WorkCrew(int helpers) {
    for (int i = 0; i < helpers; ++i)
        helpers_.emplace_back([this] { help(); });
}

WorkCrew::~WorkCrew() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    work_.notify_all();
    for (std::thread& helper : helpers_)
        helper.join();
}

void WorkCrew::run(std::size_t count, const std::function<void(std::size_t)>& job) {
    if (count == 0)
        return;
    std::unique_lock lock(mutex_);
    job_ = &job;
    count_ = count;
    next_ = 0;
    done_ = 0;
    if (count > 1)
        work_.notify_all();
    take_jobs(lock);
    finished_.wait(lock, [this] { return done_ == count_; });
    job_ = nullptr;
    count_ = 0;
}

void WorkCrew::take_jobs(std::unique_lock<std::mutex>& lock) {
    while (job_ && next_ < count_) {
        const std::size_t i = next_++;
        const auto* job = job_;
        lock.unlock();
        (*job)(i);
        lock.lock();
        if (++done_ == count_)
            finished_.notify_one();
    }
}

void WorkCrew::help() {
    std::unique_lock lock(mutex_);
    for (;;) {
        work_.wait(lock, [this] { return stopping_ || (job_ && next_ < count_); });
        if (stopping_)
            return;
        take_jobs(lock);
    }
}

} // namespace termpool::hall
