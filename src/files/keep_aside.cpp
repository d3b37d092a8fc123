#include "files/keep_aside.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>

namespace termpool {
namespace {

// Enough for any sane number of damaged files; a directory full of them is an error.
constexpr int max_candidates = 1000;

bool exists(const std::string& path) {
    struct stat st {};
    return ::lstat(path.c_str(), &st) == 0 || errno != ENOENT;
}

// rename without replacing: the kernel checks and renames in one step where the file system
// allows it; elsewhere a check just before the rename has to do.
int rename_no_replace(const std::string& from, const std::string& to) {
    if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0)
        return 0;
    if (errno != EINVAL && errno != ENOSYS)
        return -1;
    if (exists(to)) {
        errno = EEXIST;
        return -1;
    }
    return std::rename(from.c_str(), to.c_str());
}

} // namespace

std::optional<std::string> keep_aside(const std::string& path, std::string& error) {
    for (int n = 0; n < max_candidates; ++n) {
        const std::string aside = path + ".bad" + (n == 0 ? "" : "." + std::to_string(n));
        if (rename_no_replace(path, aside) == 0)
            return aside;
        if (errno != EEXIST) {
            error = path + ": cannot rename to " + aside + ": " + std::strerror(errno);
            return std::nullopt;
        }
    }
    error = path + ": " + std::to_string(max_candidates) + " older .bad files are in the way";
    return std::nullopt;
}

} // namespace termpool
