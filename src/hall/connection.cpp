#include "hall/connection.hpp"

#include <algorithm>
#include <cerrno>
#include <sys/socket.h>

#include "hall/protocol.hpp"

namespace termpool::hall {

Connection::ReadResult Connection::read() {
    char buffer[65536];
    const ssize_t n = ::recv(fd_.get(), buffer, sizeof buffer, 0);
    if (n < 0)
        return errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR ? ReadResult::ok
                                                                         : ReadResult::closed;
    if (n == 0)
        return ReadResult::closed;
    std::size_t start = 0;
    const std::string_view got(buffer, static_cast<std::size_t>(n));
    for (std::size_t end; (end = got.find('\n', start)) != std::string_view::npos;
         start = end + 1) {
        if (in_.size() + (end - start) + 1 > max_line_bytes)
            return ReadResult::too_long;
        in_.append(got.substr(start, end - start));
        lines_.push_back(std::move(in_));
        in_.clear();
    }
    in_.append(got.substr(start));
    // A partial line that can no longer end within the limit is refused at once, so the
    // buffer never holds more than one line's worth.
    return in_.size() + 1 > max_line_bytes ? ReadResult::too_long : ReadResult::ok;
}

std::string Connection::take_line() {
    std::string line = std::move(lines_.front());
    lines_.pop_front();
    return line;
}

bool Connection::queue(std::string_view bytes, std::size_t limit) {
    if (sent_ > 0 && sent_ * 2 >= out_.size()) {
        out_.erase(0, sent_); // what was sent is not kept past half the queue
        sent_ = 0;
    }
    out_.append(bytes);
    return owed() <= limit;
}

bool Connection::queue_bulk(std::string_view bytes, std::size_t limit, std::size_t allowance) {
    if (allowance_left() == 0) {
        bulk_start_ = written_ + queued(); // where these bytes will start
        bulk_end_ = bulk_start_ + std::min(bytes.size(), allowance);
    }
    return queue(bytes, limit);
}

std::size_t Connection::allowance_left() const {
    return bulk_end_ - std::clamp(written_, bulk_start_, bulk_end_);
}

bool Connection::flush() {
    while (sent_ < out_.size()) {
        // MSG_NOSIGNAL: a peer gone mid-write is an error return, not a SIGPIPE for the hall.
        const ssize_t n = ::send(fd_.get(), out_.data() + sent_, out_.size() - sent_, MSG_NOSIGNAL);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            return errno == EAGAIN || errno == EWOULDBLOCK;
        }
        sent_ += static_cast<std::size_t>(n);
        written_ += static_cast<std::size_t>(n);
    }
    // Sent in full: give the memory back rather than keep the largest burst's buffer.
    out_.clear();
    out_.shrink_to_fit();
    sent_ = 0;
    return true;
}

} // namespace termpool::hall
