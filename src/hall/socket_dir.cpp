#include "hall/socket_dir.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

namespace termpool::hall {
namespace {

// The folder part of a path: "a/b/hall.sock" -> "a/b", "/hall.sock" -> "/", "hall.sock" -> ".".
std::string folder_of(const std::string& path) {
    const std::size_t slash = path.rfind('/');
    if (slash == std::string::npos)
        return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string octal_mode(mode_t mode) {
    char text[8];
    std::snprintf(text, sizeof text, "%04o", static_cast<unsigned>(mode & 07777));
    return text;
}

} // namespace

std::string default_socket_path() {
    if (const char* runtime = std::getenv("XDG_RUNTIME_DIR"); runtime && *runtime)
        return std::string(runtime) + "/termpool/hall.sock";
    return "/tmp/termpool-" + std::to_string(::geteuid()) + "/hall.sock";
}

std::size_t max_socket_path_bytes() {
    return sizeof(sockaddr_un{}.sun_path) - 1;
}

std::string prepare_socket_dir(const std::string& socket_path) {
    if (socket_path.empty())
        return "the socket path is empty";
    if (socket_path.size() > max_socket_path_bytes())
        return socket_path + ": too long for a Unix socket (" + std::to_string(socket_path.size()) +
               " bytes, at most " + std::to_string(max_socket_path_bytes()) + ")";
    const std::string folder = folder_of(socket_path);
    if (::mkdir(folder.c_str(), 0700) != 0 && errno != EEXIST)
        return folder + ": cannot create the socket folder: " + std::strerror(errno);
    // lstat, not stat: a symbolic link could be swapped for another target after the check.
    struct stat st {};
    if (::lstat(folder.c_str(), &st) != 0)
        return folder + ": " + std::strerror(errno);
    if (S_ISLNK(st.st_mode))
        return folder + ": the socket folder is a symbolic link, not a directory";
    if (!S_ISDIR(st.st_mode))
        return folder + ": the socket folder is not a directory";
    if (st.st_uid != ::geteuid())
        return folder + ": the socket folder is owned by uid " + std::to_string(st.st_uid) +
               ", not by this user (uid " + std::to_string(::geteuid()) + ")";
    if ((st.st_mode & (S_IWGRP | S_IWOTH)) != 0)
        return folder + ": the socket folder is writable by " +
               ((st.st_mode & S_IWOTH) != 0 ? "others" : "its group") + " (mode " +
               octal_mode(st.st_mode) + "); make it private with chmod 700";
    return {};
}

} // namespace termpool::hall
