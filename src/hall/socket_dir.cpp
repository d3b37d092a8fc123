#include "hall/socket_dir.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include "hall/socket_trust.hpp"

namespace termpool::hall {

std::string socket_folder_of(const std::string& path) {
    const std::size_t slash = path.rfind('/');
    if (slash == std::string::npos)
        return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

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
    const std::string folder = socket_folder_of(socket_path);
    if (::mkdir(folder.c_str(), 0700) != 0 && errno != EEXIST)
        return folder + ": cannot create the socket folder: " + std::strerror(errno);
    // lstat, not stat: a symbolic link could be swapped for another target after the check.
    struct stat st {};
    if (::lstat(folder.c_str(), &st) != 0)
        return folder + ": " + std::strerror(errno);
    return judge_socket_folder(folder, st, ::geteuid());
}

} // namespace termpool::hall
