#include "files/atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace termpool {
namespace {

std::string problem(const std::string& path, const char* what) {
    return path + ": " + what + ": " + std::strerror(errno);
}

bool write_all(int fd, const std::string& text) {
    for (std::size_t done = 0; done < text.size();) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
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

bool write_atomically(const std::string& path, const std::string& text, std::string& error) {
    const std::size_t slash = path.rfind('/');
    const std::string folder = slash == std::string::npos ? "." : path.substr(0, slash);
    if (slash != std::string::npos) {
        if (std::string made = make_directories(folder); !made.empty()) {
            error = made;
            return false;
        }
    }
    // One name, so a writer killed midway leaves one stale file that the next save replaces.
    // Every file written here has one writer at a time: a game's save is locked to its game,
    // the statistics are written under their lock, a hall's tables by its one server.
    const std::string temporary = path + ".tmp";
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (fd < 0) {
        error = problem(temporary, "cannot create");
        return false;
    }
    error.clear();
    if (!write_all(fd, text))
        error = problem(temporary, "cannot write");
    else if (::fsync(fd) != 0)
        error = problem(temporary, "cannot sync");
    if (::close(fd) != 0 && error.empty())
        error = problem(temporary, "cannot close");
    if (error.empty() && ::rename(temporary.c_str(), path.c_str()) != 0)
        error = problem(path, ("cannot rename " + temporary + " to it").c_str());
    if (!error.empty()) {
        ::unlink(temporary.c_str());
        return false;
    }
    // The rename itself is durable once the folder is synced.
    if (const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
    return true;
}

std::optional<std::string> read_whole_file(const std::string& path, std::string& error,
                                           std::size_t max_bytes) {
    error.clear();
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        if (errno != ENOENT)
            error = problem(path, "cannot open");
        return std::nullopt;
    }
    std::string text;
    char buffer[8192];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            error = problem(path, "cannot read");
            ::close(fd);
            return std::nullopt;
        }
        if (n == 0)
            break;
        if (text.size() + static_cast<std::size_t>(n) > max_bytes) {
            error = path + ": larger than " + std::to_string(max_bytes) + " bytes";
            ::close(fd);
            return std::nullopt;
        }
        text.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(fd);
    return text;
}

} // namespace termpool
