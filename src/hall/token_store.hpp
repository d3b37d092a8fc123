#pragma once
/// \file
/// The client's seat tokens, one file per player name: a player whose connection dropped
/// proves with it, on the next `termpool hall`, that the seat kept for them is theirs. Keyed
/// by name, not by account, because every friend who comes in over SSH runs as the same `pool`
/// account, each with the name their key forces (`command="termpool hall --name NAME"`).
///
/// The folder (default $XDG_STATE_HOME/termpool/hall-tokens) holds NAMEHEX.token, NAMEHEX the
/// player name's UTF-8 bytes as lowercase hex, so that any valid name makes a safe file name
/// (no '/', no "..", no leading dot, at most 166 bytes); the file is the token and a newline,
/// mode 0600, written atomically.

#include <string>

namespace termpool::hall {

/// The default token folder: $XDG_STATE_HOME/termpool/hall-tokens
/// (~/.local/state/termpool/hall-tokens).
std::string default_token_dir();

/// The path of `name`'s token file in `dir`: DIR/HEX.token (`name` a valid player name).
std::string token_path(const std::string& dir, const std::string& name);

/// The token kept for `name` in `dir`; "" when there is none, the file cannot be read, what
/// it holds is not a token (32 lowercase hex digits), or `name` is not a valid player name.
std::string load_token(const std::string& dir, const std::string& name);

/// Keeps `token` for `name` in `dir` (made, mode 0700, if missing): written to a temporary
/// file, synced and renamed over the old one, mode 0600. "" or why not; an invalid name or a
/// text that is not a token is refused before anything is written. Two clients saving for the
/// same name at the same moment may see one of them fail (they share the temporary file's
/// name); the file then holds one of the two tokens whole.
std::string save_token(const std::string& dir, const std::string& name, const std::string& token);

} // namespace termpool::hall
