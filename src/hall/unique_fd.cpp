#include "hall/unique_fd.hpp"

#include <fcntl.h>

namespace termpool::hall {

bool make_nonblocking(int fd) {
    const int flags = ::fcntl(fd, F_GETFL);
    const int fd_flags = ::fcntl(fd, F_GETFD);
    return flags >= 0 && fd_flags >= 0 && ::fcntl(fd, F_SETFL, flags | O_NONBLOCK) == 0 &&
           ::fcntl(fd, F_SETFD, fd_flags | FD_CLOEXEC) == 0;
}

bool WakePipe::open() {
    int fds[2];
    if (::pipe(fds) != 0)
        return false;
    read_end = UniqueFd(fds[0]);
    write_end = UniqueFd(fds[1]);
    return make_nonblocking(fds[0]) && make_nonblocking(fds[1]);
}

void WakePipe::wake() const {
    const char byte = 1;
    // A full pipe already wakes the poller: a failed write loses nothing.
    [[maybe_unused]] const auto ignored = ::write(write_end.get(), &byte, 1);
}

void WakePipe::drain() const {
    char buffer[256];
    while (::read(read_end.get(), buffer, sizeof buffer) > 0) {
    }
}

} // namespace termpool::hall
