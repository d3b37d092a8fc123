#include "hall/hall_lock.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>

namespace termpool::hall {

std::string hall_lock_path(const std::string& socket_path) {
    return socket_path + ".lock";
}

std::string lock_hall(const std::string& socket_path, UniqueFd& held) {
    const std::string path = hall_lock_path(socket_path);
    // O_NOFOLLOW: a link put in the lock's place is refused, not followed.
    UniqueFd fd(::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NOCTTY, 0600));
    if (!fd)
        return path + ": cannot open the hall's lock: " + std::strerror(errno);
    while (::flock(fd.get(), LOCK_EX | LOCK_NB) != 0) {
        if (errno == EINTR)
            continue;
        if (errno == EWOULDBLOCK)
            return "a hall is already starting/running at " + socket_path;
        return path + ": cannot lock: " + std::strerror(errno);
    }
    held = std::move(fd);
    return {};
}

} // namespace termpool::hall
