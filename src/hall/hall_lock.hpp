#pragma once
/// \file
/// One hall per socket. A server's open() refuses a socket a live server answers on, but two
/// servers started at the same moment could both find it dead, and the second would unlink
/// the first one's new socket and bind its own. So `termpool hall serve` first takes an
/// exclusive flock(2) on PATH.lock beside the socket and holds it for its life: of two servers
/// started together (two players' `termpool hall` finding no hall), one serves and the other
/// exits. The lock file stays (removing it would let a third server lock a new file while the
/// first still holds the old one).

#include <string>

#include "hall/unique_fd.hpp"

namespace termpool::hall {

/// The lock file of the hall at `socket_path`: PATH.lock, in the socket's own folder.
std::string hall_lock_path(const std::string& socket_path);

/// Takes the exclusive lock on hall_lock_path(socket_path) (the file made, mode 0600, if
/// missing) without waiting; `held` keeps it until it is closed or the process ends. "" when
/// taken; "a hall is already starting/running at PATH" when another holds it; else why not.
std::string lock_hall(const std::string& socket_path, UniqueFd& held);

/// The same for the state folder's hall.lock: two servers on two sockets (a systemd unit and
/// a terminal whose session has another XDG_RUNTIME_DIR) must not both write one folder's
/// tables. "" when taken; "another hall already keeps its tables in DIR" when held.
std::string lock_state_dir(const std::string& state_dir, UniqueFd& held);

} // namespace termpool::hall
