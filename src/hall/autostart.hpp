#pragma once
/// \file
/// `termpool hall` finds the hall running, or starts one in the background as tmux starts its
/// server: the server detaches into a session of its own (no controlling terminal, so that
/// closing the player's terminal or SSH session does not take it down), its stdin and stdout
/// on /dev/null and its stderr appended to hall.log in the default state folder, and it runs
/// with `--idle-exit 60`, so that it goes once nobody has used it for a minute.

#include <chrono>
#include <string>
#include <sys/types.h>
#include <vector>

#include "hall/client.hpp"
#include "hall/hall_state.hpp"

namespace termpool::hall {

/// How long connect_or_start waits for a server it started to answer.
inline constexpr std::chrono::milliseconds hall_start_wait{5000};

/// This program's own path (/proc/self/exe), to start the server with: the same build as the
/// client, wherever it was started from; "" when the system does not tell.
std::string own_executable();

/// The log of a hall started in the background: hall.log in its state folder `state` (by
/// default default_state_dir(); connect_or_start gives it resolved, as the server uses it).
std::string started_hall_log_path(const std::string& state = default_state_dir());

/// What connect_or_start came to.
struct HallReach {
    /// "" when connected, else why not.
    std::string error;
    /// The started server's log file (started_hall_log_path()), or "" when a running hall
    /// answered.
    std::string started_log;
    /// The socket's folder or file, or the server that answered, is not this user's alone
    /// (hall/socket_trust.hpp), or the state folder a started hall would use is not: nothing
    /// was sent there, and trying again would not help.
    bool refused = false;
};

/// Connects `client` to the hall at `socket_path`, trusting only this user's own: before each
/// try the socket's folder and file are checked (check_socket_path) and after it the server's
/// uid (check_peer); a hall that fails either is refused at once (`refused`, nothing sent, the
/// client left closed), never replaced by a started one. When nothing answers (no socket file,
/// or a stale one nobody listens on), makes the socket's folder (prepare_socket_dir), starts
/// `self_exe hall serve --socket SOCKET_PATH --idle-exit 60` detached, and tries to connect
/// again every 20 ms for up to hall_start_wait; should the server it started exit meanwhile
/// without anyone answering (another hall was just going away and held the lock), it starts
/// one again, three times at most. Of two clients doing this at once, both end up on the one
/// server that took the socket's lock (hall/hall_lock.hpp). The error is the refusal, the
/// connection's error when something other than "nothing there" stopped it, the folder's
/// problem, or, when the started server never answered, the last line of its log.
HallReach connect_or_start(HallClient& client, const std::string& socket_path,
                           const std::string& self_exe);

/// Starts `args` (args[0] the program's path) detached: fork, setsid, fork again (the first
/// child exits at once and is reaped, so no zombie stays and the server cannot get a
/// controlling terminal), stdin and stdout /dev/null, stderr appended to `log_path` (made
/// 0600), every other descriptor closed, signals as the program would get them from a shell,
/// the working folder and environment kept. The server's process id, or 0 with `error` set
/// (an exec that fails is reported here, not left to a timeout).
pid_t start_detached(const std::vector<std::string>& args, const std::string& log_path,
                     std::string& error);

} // namespace termpool::hall
