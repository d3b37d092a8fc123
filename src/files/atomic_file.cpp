#include "files/atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <string_view>
#include <sys/random.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

namespace termpool {
namespace {

constexpr std::string_view temporary_mark = ".tmp";
constexpr std::size_t suffix_length = 6;
constexpr std::string_view suffix_letters =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";

std::string problem(const std::string& path, const char* what) {
    return path + ": " + what + ": " + std::strerror(errno);
}

bool write_all(int fd, const std::string& text) {
    for (std::size_t done = 0; done < text.size();) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n == 0)
            errno = ENOSPC; // write(2) makes no progress only when the device is full
        if (n <= 0)
            return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

// Six letters or digits from getrandom; a clock and the process id where it gives none, which
// O_EXCL makes safe all the same (only guessable, so a planted name costs a retry).
std::string random_suffix() {
    unsigned char bytes[suffix_length] = {};
    if (::getrandom(bytes, sizeof bytes, GRND_NONBLOCK) != static_cast<ssize_t>(sizeof bytes)) {
        timespec now{};
        ::clock_gettime(CLOCK_MONOTONIC, &now);
        const auto mix = static_cast<unsigned long long>(now.tv_nsec) ^
                         (static_cast<unsigned long long>(::getpid()) << 20);
        for (std::size_t i = 0; i < suffix_length; ++i)
            bytes[i] = static_cast<unsigned char>(mix >> (8 * i));
    }
    std::string suffix;
    for (const unsigned char b : bytes)
        suffix += suffix_letters[b % suffix_letters.size()];
    return suffix;
}

// create_temporary without the message: -1 with errno set on failure.
int open_temporary(const std::string& path, std::string& temporary,
                   const std::function<std::string()>& next_suffix) {
    for (int attempt = 0; attempt < temporary_name_attempts; ++attempt) {
        temporary = path + std::string(temporary_mark) + "." +
                    (next_suffix ? next_suffix() : random_suffix());
        // O_EXCL fails on any name that exists, a link (even a dangling one) included.
        const int fd =
            ::open(temporary.c_str(),
                   O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY, 0600);
        if (fd >= 0 || errno != EEXIST)
            return fd;
    }
    errno = EEXIST;
    return -1;
}

std::string folder_of(const std::string& path) {
    const std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
}

void sync_folder(const std::string& folder) {
    if (const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
}

} // namespace

std::string make_directories(const std::string& dir) {
    for (std::size_t i = 1; i <= dir.size(); ++i)
        if (i == dir.size() || dir[i] == '/') {
            const std::string part = dir.substr(0, i);
            if (::mkdir(part.c_str(), 0700) != 0 && errno != EEXIST)
                return problem(part, "cannot create the folder");
        }
    return {};
}

int create_temporary(const std::string& path, std::string& temporary, std::string& error,
                     const std::function<std::string()>& next_suffix) {
    const int fd = open_temporary(path, temporary, next_suffix);
    if (fd < 0)
        error = errno == EEXIST ? path + std::string(temporary_mark) +
                                      ".*: " + std::to_string(temporary_name_attempts) +
                                      " names tried, each taken by another file"
                                : problem(temporary, "cannot create");
    return fd;
}

bool write_atomically(const std::string& path, const std::string& text, std::string& error) {
    error.clear();
    const std::string folder = folder_of(path);
    if (path.find('/') != std::string::npos) {
        if (std::string made = make_directories(folder); !made.empty()) {
            error = made;
            return false;
        }
    }
    std::string temporary;
    const int fd = create_temporary(path, temporary, error);
    if (fd < 0)
        return false;
    if (!write_all(fd, text))
        error = problem(temporary, "cannot write");
    else if (::fsync(fd) != 0)
        error = problem(temporary, "cannot sync");
    if (::close(fd) != 0 && error.empty())
        error = problem(temporary, "cannot close");
    // rename replaces the name PATH, never what a link there points to.
    if (error.empty() && ::rename(temporary.c_str(), path.c_str()) != 0)
        error = problem(path, ("cannot rename " + temporary + " to it").c_str());
    if (!error.empty()) {
        ::unlink(temporary.c_str());
        return false;
    }
    sync_folder(folder); // the rename itself is durable once the folder is synced
    return true;
}

void remove_temporaries_of(const std::string& path) {
    const std::string folder = folder_of(path);
    const std::size_t slash = path.rfind('/');
    const std::string stem =
        (slash == std::string::npos ? path : path.substr(slash + 1)) + std::string(temporary_mark);
    DIR* dir = ::opendir(folder.c_str());
    if (!dir)
        return;
    while (const dirent* entry = ::readdir(dir)) {
        const std::string_view name = entry->d_name;
        if (!name.starts_with(stem))
            continue;
        const std::string_view rest = name.substr(stem.size());
        const bool ours = rest.empty() || (rest.size() == 1 + suffix_length && rest[0] == '.' &&
                                           rest.substr(1).find_first_not_of(suffix_letters) ==
                                               std::string_view::npos);
        // unlinkat removes the name, a link's own; a folder there fails and stays.
        if (ours)
            ::unlinkat(::dirfd(dir), entry->d_name, 0);
    }
    ::closedir(dir);
}

std::string can_write_in(const std::string& dir) {
    if (std::string made = make_directories(dir); !made.empty())
        return made;
    // A block, not an empty file: a full file system still makes empty files.
    const std::string block(4096, '\n');
    std::string temporary;
    const int fd = open_temporary(dir + "/.termpool-write-check", temporary, {});
    if (fd < 0)
        return problem(dir, "cannot save there");
    std::string why;
    if (!write_all(fd, block) || ::fsync(fd) != 0)
        why = problem(dir, "cannot save there");
    ::close(fd);
    ::unlink(temporary.c_str());
    return why;
}

} // namespace termpool
