#include "files/self_command.hpp"

#include <array>
#include <cstdlib>
#include <string_view>
#include <sys/stat.h>
#include <unistd.h>

namespace termpool {

namespace {

// The same file: the same device and inode.
bool same_file(const std::string& path, const struct stat& self) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && st.st_dev == self.st_dev && st.st_ino == self.st_ino;
}

// True when the first `termpool` a shell would find on $PATH is the file `self`.
bool found_on_path(const struct stat& self) {
    const char* path = std::getenv("PATH");
    if (!path)
        return false;
    std::string_view rest = path;
    while (true) {
        const std::size_t colon = rest.find(':');
        const std::string_view dir = rest.substr(0, colon);
        // An empty entry is the current folder, as for the shell.
        const std::string candidate =
            (dir.empty() ? std::string(".") : std::string(dir)) + "/termpool";
        if (::access(candidate.c_str(), X_OK) == 0)
            return same_file(candidate, self); // the shell would run this one, whichever it is
        if (colon == std::string_view::npos)
            return false;
        rest.remove_prefix(colon + 1);
    }
}

} // namespace

std::string self_command() {
    std::array<char, 4096> buffer{};
    const ssize_t n = ::readlink("/proc/self/exe", buffer.data(), buffer.size() - 1);
    struct stat self {};
    if (n <= 0 || ::stat("/proc/self/exe", &self) != 0)
        return "termpool";
    if (found_on_path(self))
        return "termpool";
    return std::string(buffer.data(), static_cast<std::size_t>(n));
}

} // namespace termpool
