#pragma once
/// \file
/// Seat tokens: the secret a client keeps to prove, when it reconnects, that an away seat is
/// its own. The server keeps only a hash of each token (in memory and in the state folder).

#include <string>
#include <string_view>

namespace termpool::hall {

/// A new token: 32 lower-case hex digits from the system's random source (/dev/urandom, or
/// std::random_device when it cannot be read).
std::string new_token();

/// The hash kept for `token`: 16 lower-case hex digits (FNV-1a, 64 bits). It only keeps a
/// state folder's reader from learning the tokens; the tokens themselves are random.
std::string token_hash(std::string_view token);

} // namespace termpool::hall
