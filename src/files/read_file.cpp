#include "files/read_file.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace termpool {
namespace {

std::string problem(const std::string& path, const char* what, int error) {
    return path + ": " + what + ": " + std::strerror(error);
}

} // namespace

std::string too_large_message(const std::string& file, unsigned long long bytes,
                              std::size_t max_bytes) {
    return file + ": " + std::to_string(bytes) + " bytes, more than the " +
           std::to_string(max_bytes) + " allowed";
}

std::optional<std::string> read_bounded(int fd, const std::string& name, std::size_t max_bytes,
                                        std::string& error) {
    error.clear();
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        error = problem(name, "cannot read", errno);
        return std::nullopt;
    }
    if (S_ISDIR(st.st_mode)) {
        error = problem(name, "cannot read", EISDIR);
        return std::nullopt;
    }
    // /proc's files say 0 and are read to their end like a pipe.
    if (S_ISREG(st.st_mode) && static_cast<unsigned long long>(st.st_size) > max_bytes) {
        error = too_large_message(name, static_cast<unsigned long long>(st.st_size), max_bytes);
        return std::nullopt;
    }
    std::string text;
    if (S_ISREG(st.st_mode))
        text.reserve(static_cast<std::size_t>(st.st_size));
    char buffer[65536];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            error = problem(name, "cannot read", errno);
            return std::nullopt;
        }
        if (n == 0)
            return text;
        if (text.size() + static_cast<std::size_t>(n) > max_bytes) {
            // It grew while being read, or is a pipe: what it holds is more than the bound.
            error = too_large_message(name, text.size() + static_cast<std::size_t>(n), max_bytes);
            return std::nullopt;
        }
        text.append(buffer, static_cast<std::size_t>(n));
    }
}

std::optional<std::string> read_whole_file(const std::string& path, std::string& error,
                                           std::size_t max_bytes, Links links) {
    error.clear();
    const int flags =
        O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY | (links == Links::no_follow ? O_NOFOLLOW : 0);
    const int fd = ::open(path.c_str(), flags);
    if (fd < 0) {
        if (errno == ELOOP && links == Links::no_follow)
            error = path + ": a symbolic link, not read";
        else if (errno != ENOENT && errno != ENOTDIR) // a file under a file: missing too
            error = problem(path, "cannot open", errno);
        return std::nullopt;
    }
    struct stat st {};
    std::optional<std::string> text;
    if (::fstat(fd, &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode))
        error = path + ": not a regular file";
    else
        text = read_bounded(fd, path, max_bytes, error);
    ::close(fd);
    return text;
}

} // namespace termpool
