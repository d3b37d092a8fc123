#pragma once
// Where the hall's socket lives, and the check that nobody else can reach into its folder.
// The rule is tmux's, made strict: the folder is made by its user with mode 0700, and a folder
// that is not a directory, belongs to someone else, or grants its group or others anything is
// refused, since whoever can write there can put their own socket in the server's place, and
// whoever can reach in can talk to the hall. The server and the client judge it the same way
// (hall/socket_trust.hpp).

#include <cstddef>
#include <string>

namespace termpool::hall {

/// The default socket: $XDG_RUNTIME_DIR/termpool/hall.sock, or /tmp/termpool-UID/hall.sock
/// when XDG_RUNTIME_DIR is unset or empty.
std::string default_socket_path();

/// The folder part of a socket path: "a/b/hall.sock" -> "a/b", "/hall.sock" -> "/",
/// "hall.sock" -> ".".
std::string socket_folder_of(const std::string& path);

/// Longest socket path a Unix socket address holds, in bytes (sun_path less its NUL).
std::size_t max_socket_path_bytes();

/// Creates the socket's folder (mode 0700) if missing, and checks it (judge_socket_folder): a
/// directory (not a symbolic link) owned by this user, with no permission for group or others.
/// Only the last folder is made: its parent ($XDG_RUNTIME_DIR, /tmp) must exist. An empty
/// string when all is well, else why not, naming the folder and its owner ("FOLDER: the socket
/// folder is owned by uid 0 (root), not by this user (uid 1000 (ann))"); a path longer than
/// `max_socket_path_bytes` is refused.
std::string prepare_socket_dir(const std::string& socket_path);

} // namespace termpool::hall
