#pragma once
/// \file
/// Whether a hall's socket may be trusted with a player's name and seat token: its folder and
/// the socket file are this user's alone, and the process that answers runs as this user.
/// Another local user who makes /tmp/termpool-UID first (or any folder on a --socket path)
/// could otherwise listen there, take the token and show a lobby of their own. The folder and
/// file are looked at (lstat) before connecting, the server's uid (SO_PEERCRED) after, before
/// anything is sent. The state folder and its table files are judged here too, by the same
/// rule of ownership: whoever else could write there could plant a seat token. The judgements
/// are pure functions of what lstat and SO_PEERCRED give, so that an owner other than oneself
/// can be tested without root.

#include <string>
#include <sys/stat.h>
#include <sys/types.h>

namespace termpool::hall {

/// Who `uid` is, for a message: "uid 1002 (mallory)", or "uid 1002" when the system has no
/// name for it.
std::string describe_uid(uid_t uid);

/// The socket folder's lstat `st` judged for `user`: a directory, not a symbolic link, owned
/// by `user`, with no permission for its group or others (tmux's rule, made strict: whoever
/// can reach into the folder can reach the hall). "" when good, else why not, naming the
/// folder and its owner ("F: the socket folder is owned by uid 1002 (mallory), not by this
/// user (uid 1001 (ann))").
std::string judge_socket_folder(const std::string& folder, const struct stat& st, uid_t user);

/// The state folder's lstat `st` (its path resolved first: check_state_folder) judged for
/// `user`: a directory owned by `user` that neither its group (unless it is the user's
/// `private_group`) nor others may write to, since whoever can write there can plant a table
/// file with a seat token of their own choosing, or hold the folder's lock so that no hall
/// starts. Reading is left to the host. "" when good, else why not, in judge_socket_folder's
/// words.
std::string judge_state_folder(const std::string& folder, const struct stat& st, uid_t user,
                               bool private_group = false);

/// Whether `group` is `user`'s own private group: the user's primary group, with no member but
/// the user (the user private groups of Debian and Ubuntu, under whose umask 002 folders are
/// made group-writable). Writing allowed to it is writing allowed to the user alone.
bool is_private_group(gid_t group, uid_t user);

/// A table file's lstat `st` judged for `user`: owned by `user`; one that is someone else's
/// was put there by them, and is not restored. "" or why not (what it is, a link or a file, is
/// the reader's to judge).
std::string judge_table_file(const std::string& path, const struct stat& st, uid_t user);

/// The socket file's lstat `st` judged for `user`: a socket owned by `user`. "" or why not,
/// naming the path and its owner.
std::string judge_socket_file(const std::string& path, const struct stat& st, uid_t user);

/// The uid of the process that answered at `path` (SO_PEERCRED) judged for `user`: the same
/// uid, or why not, naming the path and who runs the hall there.
std::string judge_peer(const std::string& path, uid_t peer, uid_t user);

/// Before connecting to `socket_path`: its folder and, when there, the socket file, as they
/// are now (lstat), judged for this user (geteuid). Nothing there yet (no folder, or no file)
/// is no problem: "". Else why not.
std::string check_socket_path(const std::string& socket_path);

/// A folder above the state folder (lstat `st`) judged for `user`: owned by `user` or root, and
/// not writable by its group (unless it is the user's `private_group`) or others unless it has
/// the sticky bit (as /tmp has), since whoever may rename entries in it could swap the state
/// folder under the hall (Debian's sshd judges the folders above authorized_keys so). "" or
/// why not.
std::string judge_folder_above(const std::string& folder, const struct stat& st, uid_t user,
                               bool private_group = false);

/// The state folder as it is now, judged for this user (geteuid) before a server locks it and
/// reads its tables: `folder` resolved through its links (realpath), the folder itself by
/// judge_state_folder and every folder above it by judge_folder_above. On success `folder`
/// becomes the resolved path, which the caller uses from then on; "" or why not.
std::string check_state_folder(std::string& folder);

/// After connecting on `fd` to `socket_path`: the process at the other end runs as this user
/// (geteuid; SO_PEERCRED gives the uid the server listened with). "" or why not.
std::string check_peer(int fd, const std::string& socket_path);

} // namespace termpool::hall
