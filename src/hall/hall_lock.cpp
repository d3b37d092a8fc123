#include "hall/hall_lock.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "hall/socket_trust.hpp"

namespace termpool::hall {

std::string hall_lock_path(const std::string& socket_path) {
    return socket_path + ".lock";
}

namespace {

// Takes the exclusive lock on the file `path` without waiting; `busy` is the answer when
// another process holds it.
std::string take_lock(const std::string& path, const std::string& busy, UniqueFd& held) {
    // A lock file someone else made is one they can hold open, flocked, for as long as they
    // like, and no hall would start: it is said so, not taken for another hall. (Looked at
    // before it is opened: their file is seldom ours to open.)
    const auto theirs = [&](uid_t owner) {
        return path + ": the hall's lock is owned by " + describe_uid(owner) + ", not by " +
               "this user (" + describe_uid(::geteuid()) +
               "); someone else put it there: remove it";
    };
    struct stat st {};
    if (::lstat(path.c_str(), &st) == 0 && st.st_uid != ::geteuid())
        return theirs(st.st_uid);
    // O_NOFOLLOW: a link put in the lock's place is refused, not followed.
    UniqueFd fd(::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NOCTTY, 0600));
    if (!fd)
        return path + ": cannot open the hall's lock: " + std::strerror(errno);
    // Made between the look and the open by someone else: the same answer.
    if (::fstat(fd.get(), &st) != 0)
        return path + ": cannot look at the hall's lock: " + std::strerror(errno);
    if (st.st_uid != ::geteuid())
        return theirs(st.st_uid);
    while (::flock(fd.get(), LOCK_EX | LOCK_NB) != 0) {
        if (errno == EINTR)
            continue;
        if (errno == EWOULDBLOCK)
            return busy;
        return path + ": cannot lock: " + std::strerror(errno);
    }
    held = std::move(fd);
    return {};
}

} // namespace

std::string lock_hall(const std::string& socket_path, UniqueFd& held) {
    return take_lock(hall_lock_path(socket_path),
                     "a hall is already starting/running at " + socket_path, held);
}

std::string lock_state_dir(const std::string& state_dir, UniqueFd& held) {
    return take_lock(state_dir + "/hall.lock",
                     "another hall already keeps its tables in " + state_dir, held);
}

} // namespace termpool::hall
