#include "hall/socket_trust.hpp"

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <grp.h>
#include <pwd.h>
#include <sys/socket.h>
#include <unistd.h>
#include <vector>

#include "hall/socket_dir.hpp"

namespace termpool::hall {
namespace {

std::string octal_mode(mode_t mode) {
    char text[8];
    std::snprintf(text, sizeof text, "%04o", static_cast<unsigned>(mode & 07777));
    return text;
}

// Who may reach into a folder of mode `mode`, worst first.
std::string reached_by(mode_t mode) {
    if ((mode & S_IWOTH) != 0)
        return "writable by others";
    if ((mode & S_IWGRP) != 0)
        return "writable by its group";
    if ((mode & S_IRWXO) != 0)
        return "open to others";
    return "open to its group";
}

std::string this_user(uid_t user) {
    return "this user (" + describe_uid(user) + ")";
}

} // namespace

std::string describe_uid(uid_t uid) {
    std::string text = "uid " + std::to_string(uid);
    // getpwuid_r, not getpwuid: the client may look from two threads (tests do).
    std::vector<char> buffer(16384);
    passwd entry{};
    passwd* found = nullptr;
    if (::getpwuid_r(uid, &entry, buffer.data(), buffer.size(), &found) == 0 && found &&
        found->pw_name && *found->pw_name)
        text += std::string(" (") + found->pw_name + ")";
    return text;
}

namespace {

// The judgement of a folder only `user` may change: `what` names it in messages, `forbidden`
// is the mode bits its group and others may not have, and `remedy` says how to take them away.
std::string judge_own_folder(const std::string& folder, const struct stat& st, uid_t user,
                             const char* what, mode_t forbidden, const char* remedy) {
    const std::string owner = "owned by " + describe_uid(st.st_uid);
    // A link could be pointed elsewhere after the check, by whoever owns the folder it is in.
    if (S_ISLNK(st.st_mode))
        return folder + ": " + what + " is a symbolic link (" + owner + "), not a directory";
    if (!S_ISDIR(st.st_mode))
        return folder + ": " + what + " is not a directory (" + owner + ")";
    if (st.st_uid != user)
        return folder + ": " + what + " is " + owner + ", not by " + this_user(user);
    if ((st.st_mode & forbidden) != 0)
        return folder + ": " + what + " is " + reached_by(st.st_mode) + " (mode " +
               octal_mode(st.st_mode) + ", " + owner + "); " + remedy;
    return {};
}

} // namespace

std::string judge_socket_folder(const std::string& folder, const struct stat& st, uid_t user) {
    return judge_own_folder(folder, st, user, "the socket folder", S_IRWXG | S_IRWXO,
                            "make it private with chmod 700");
}

// Who may not write to the state folder or a folder above it: others, and its group unless
// that is the user's own private group (Debian's rule for the folders sshd judges: with umask
// 002, mkdir -p makes such folders group-writable, and its group is the user alone).
namespace {

mode_t writers_refused(bool private_group) {
    return private_group ? S_IWOTH : S_IWGRP | S_IWOTH;
}

} // namespace

std::string judge_state_folder(const std::string& folder, const struct stat& st, uid_t user,
                               bool private_group) {
    return judge_own_folder(folder, st, user, "the state folder", writers_refused(private_group),
                            "let no one else write to it: chmod go-w");
}

bool is_private_group(gid_t group, uid_t user) {
    std::vector<char> buffer(16384);
    passwd account{};
    passwd* found_account = nullptr;
    if (::getpwuid_r(user, &account, buffer.data(), buffer.size(), &found_account) != 0 ||
        !found_account || account.pw_gid != group || !account.pw_name)
        return false;
    const std::string name = account.pw_name;
    std::vector<char> group_buffer(65536);
    struct group entry {};
    struct group* found_group = nullptr;
    if (::getgrgid_r(group, &entry, group_buffer.data(), group_buffer.size(), &found_group) != 0 ||
        !found_group)
        return false;
    // Its members by name: none, or only the user.
    for (char** member = entry.gr_mem; member && *member; ++member)
        if (name != *member)
            return false;
    return true;
}

std::string judge_table_file(const std::string& path, const struct stat& st, uid_t user) {
    if (st.st_uid != user)
        return path + ": the table file is owned by " + describe_uid(st.st_uid) + ", not by " +
               this_user(user) + "; someone else put it there";
    return {};
}

std::string judge_socket_file(const std::string& path, const struct stat& st, uid_t user) {
    const std::string owner = "owned by " + describe_uid(st.st_uid);
    if (!S_ISSOCK(st.st_mode))
        return path + ": not a socket (" + owner + ")";
    if (st.st_uid != user)
        return path + ": the hall's socket is " + owner + ", not by " + this_user(user);
    return {};
}

std::string judge_peer(const std::string& path, uid_t peer, uid_t user) {
    if (peer == user)
        return {};
    return path + ": the hall there runs as " + describe_uid(peer) + ", not as " + this_user(user) +
           "; nothing was sent to it";
}

std::string check_socket_path(const std::string& socket_path) {
    const uid_t user = ::geteuid();
    const std::string folder = socket_folder_of(socket_path);
    struct stat st {};
    if (::lstat(folder.c_str(), &st) != 0)
        return errno == ENOENT ? std::string() : folder + ": " + std::strerror(errno);
    if (std::string problem = judge_socket_folder(folder, st, user); !problem.empty())
        return problem;
    if (::lstat(socket_path.c_str(), &st) != 0)
        return errno == ENOENT ? std::string() : socket_path + ": " + std::strerror(errno);
    return judge_socket_file(socket_path, st, user);
}

std::string judge_folder_above(const std::string& folder, const struct stat& st, uid_t user,
                               bool private_group) {
    if (st.st_uid != user && st.st_uid != 0)
        return folder + ": a folder above the state folder is owned by " + describe_uid(st.st_uid) +
               ", who could put another in its place; keep the state in a folder of your own";
    if ((st.st_mode & writers_refused(private_group)) != 0 && (st.st_mode & S_ISVTX) == 0)
        return folder + ": a folder above the state folder is " + reached_by(st.st_mode) +
               " (mode " + octal_mode(st.st_mode) +
               "), so that the state folder could be swapped under the hall; keep the state in a "
               "folder of your own";
    return {};
}

std::string check_state_folder(std::string& folder) {
    // The folder as it really is, links resolved once: the hall uses this path from now on,
    // so that a link repointed later takes nothing with it.
    char real[PATH_MAX];
    if (::realpath(folder.c_str(), real) == nullptr)
        return folder + ": " + std::strerror(errno);
    const std::string resolved = real;
    struct stat st {};
    if (::lstat(resolved.c_str(), &st) != 0)
        return resolved + ": " + std::strerror(errno);
    const uid_t user = ::geteuid();
    if (std::string problem =
            judge_state_folder(resolved, st, user, is_private_group(st.st_gid, user));
        !problem.empty())
        return problem;
    // Each folder above: whoever may rename entries in one (its owner, or anyone who may write
    // to it without the sticky bit /tmp has) could swap the state folder for one of theirs.
    for (std::string above = resolved; above != "/";) {
        const std::size_t slash = above.find_last_of('/');
        above = slash == 0 ? "/" : above.substr(0, slash);
        if (::lstat(above.c_str(), &st) != 0)
            return above + ": " + std::strerror(errno);
        if (std::string problem =
                judge_folder_above(above, st, user, is_private_group(st.st_gid, user));
            !problem.empty())
            return problem;
    }
    folder = resolved;
    return {};
}

std::string check_peer(int fd, const std::string& socket_path) {
    ucred peer{};
    socklen_t size = sizeof peer;
    if (::getsockopt(fd, SOL_SOCKET, SO_PEERCRED, &peer, &size) != 0)
        return socket_path + ": cannot tell who runs the hall there: " + std::strerror(errno);
    return judge_peer(socket_path, peer.uid, ::geteuid());
}

} // namespace termpool::hall
