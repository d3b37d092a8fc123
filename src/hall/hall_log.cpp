#include "hall/hall_log.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace termpool::hall {
namespace {

// Budgets kept at most: one per client and kind is a few hundred; beyond this (clients
// coming and going faster than their budgets refill) the new ones share one per kind.
constexpr std::size_t max_budgets = 4096;
constexpr int shared_client = -1;

UniqueFd open_log_file(const std::string& path) {
    // Appended to, never through a link someone planted in the state folder.
    return UniqueFd(
        ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0600));
}

} // namespace

HallLog::HallLog(HallLogOptions options) : options_(std::move(options)) {}

HallLog::HallLog(std::ostream& stream) {
    options_.stream = &stream;
}

std::string HallLog::open() {
    if (options_.path.empty())
        return {};
    UniqueFd fd = open_log_file(options_.path);
    if (!fd)
        return options_.path + ": " + std::strerror(errno);
    struct stat st {};
    if (::fstat(fd.get(), &st) != 0 || !S_ISREG(st.st_mode))
        return options_.path + ": not a regular file";
    const std::lock_guard lock(mutex_);
    file_ = std::move(fd);
    return {};
}

std::string HallLog::timestamp(std::chrono::system_clock::time_point time) {
    using namespace std::chrono;
    const auto ms = floor<milliseconds>(time.time_since_epoch()).count();
    const auto seconds = static_cast<std::time_t>(ms >= 0 ? ms / 1000 : (ms - 999) / 1000);
    const int millis = static_cast<int>(ms - static_cast<long long>(seconds) * 1000);
    std::tm t{};
    ::gmtime_r(&seconds, &t);
    char text[96]; // room for any int the fields could hold
    std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", t.tm_year + 1900,
                  t.tm_mon + 1, t.tm_mday, t.tm_hour, t.tm_min, t.tm_sec, millis);
    return text;
}

std::chrono::system_clock::time_point HallLog::now() const {
    return options_.clock ? options_.clock() : std::chrono::system_clock::now();
}

void HallLog::write(std::string_view line) {
    const std::lock_guard lock(mutex_);
    const auto at = now();
    sweep(at);
    emit(at, line);
}

void HallLog::write_repeated(int client, std::string_view kind, std::string_view line) {
    const std::lock_guard lock(mutex_);
    const auto at = now();
    sweep(at);
    Key key{client, std::string(kind)};
    if (budgets_.size() >= max_budgets && !budgets_.count(key))
        key.first = shared_client;
    const auto [found, fresh] = budgets_.try_emplace(key);
    Budget& budget = found->second;
    if (fresh) {
        budget.tokens = options_.burst;
        budget.last = at;
    }
    if (!refill(budget, at)) {
        ++budget.left_out;
        ++left_out_;
        return;
    }
    budget.tokens -= 1;
    if (budget.left_out > 0)
        emit(at, left_out_line(key, std::exchange(budget.left_out, 0)));
    emit(at, line);
}

std::uint64_t HallLog::left_out() const {
    const std::lock_guard lock(mutex_);
    return left_out_;
}

// Counts the tokens earned since the budget was last counted; true when one is there.
bool HallLog::refill(Budget& budget, std::chrono::system_clock::time_point at) const {
    const double elapsed = std::max(0.0, std::chrono::duration<double>(at - budget.last).count());
    const double interval =
        std::max(1.0, static_cast<double>(options_.repeat_interval.count())); // seconds
    budget.tokens = std::min(options_.burst, budget.tokens + elapsed / interval);
    budget.last = std::max(budget.last, at);
    return budget.tokens >= 1;
}

// Once an interval: what was left out of a kind that has gone quiet is told now rather than
// never, and a budget that is full again is forgotten (its client has most likely gone).
void HallLog::sweep(std::chrono::system_clock::time_point at) {
    if (at - last_sweep_ < options_.repeat_interval && at >= last_sweep_)
        return;
    last_sweep_ = at;
    for (auto it = budgets_.begin(); it != budgets_.end();) {
        Budget& budget = it->second;
        if (refill(budget, at) && budget.left_out > 0)
            emit(at, left_out_line(it->first, std::exchange(budget.left_out, 0)));
        if (budget.tokens >= options_.burst && budget.left_out == 0)
            it = budgets_.erase(it);
        else
            ++it;
    }
}

std::string HallLog::left_out_line(const Key& key, std::uint64_t count) {
    const std::string who =
        key.first == shared_client ? "clients" : "client " + std::to_string(key.first);
    return who + ": " + std::to_string(count) + " more '" + key.second +
           "' lines left out (the log takes a few at once, then one a minute)";
}

void HallLog::emit(std::chrono::system_clock::time_point at, std::string_view line) {
    std::string text = timestamp(at) + " termpool hall: ";
    text += line;
    text += '\n';
    if (file_)
        rotate_if_full(text.size());
    if (!file_) {
        if (options_.stream)
            *options_.stream << text << std::flush;
        return;
    }
    // A failed write is dropped: the log must never stop the hall.
    for (std::string_view rest = text; !rest.empty();) {
        const ssize_t n = ::write(file_.get(), rest.data(), rest.size());
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        rest.remove_prefix(static_cast<std::size_t>(n));
    }
}

void HallLog::rotate_if_full(std::size_t adding) {
    struct stat old {};
    if (options_.cap_bytes == 0 || ::fstat(file_.get(), &old) != 0 || old.st_size == 0 ||
        static_cast<std::uint64_t>(old.st_size) + adding <= options_.cap_bytes)
        return;
    const std::string kept = options_.path + ".1";
    if (::rename(options_.path.c_str(), kept.c_str()) != 0)
        return; // written on past the cap rather than lost
    UniqueFd fresh = open_log_file(options_.path);
    if (!fresh) {
        file_.reset(); // the stream, if any, takes the lines from now on
        return;
    }
    // A stderr that was the log (a hall started in the background) follows it, so that what
    // else comes there does not grow the old file.
    struct stat err {};
    if (::fstat(STDERR_FILENO, &err) == 0 && err.st_dev == old.st_dev && err.st_ino == old.st_ino)
        ::dup2(fresh.get(), STDERR_FILENO);
    file_ = std::move(fresh);
}

} // namespace termpool::hall
