#pragma once
// One save read back: the file (bounded, a regular file only) and the game it holds, replayed
// to where it stands. Reading never changes the file; moving aside a save that is not a game is
// the caller's decision.

#include "files/file_limits.hpp"

#include <optional>
#include <string>
#include <termpool/match.hpp>
#include <termpool/record.hpp>
#include <variant>

namespace termpool {

/// A save's text read back as a game: the record parsed and replayed to where it stands, or
/// why it is not a game (the line and the problem).
std::variant<Match, RecordError> load_game(const std::string& text);

/// True when `game` is over: the game, or the match, is won. Such a save is kept for
/// `termpool replay` but is never offered to continue, and a new game may take its place.
bool finished(const Match& game);

/// What reading a save gave.
struct SaveContents {
    std::optional<std::string> text;    ///< the file, when it could be read
    std::string error;                  ///< why it could not be read ("" when read or missing)
    std::optional<RecordError> problem; ///< why the text is not a game
    std::optional<Match> game;          ///< the game or match as it stands

    /// True when there is no file at all.
    bool missing() const { return !text && error.empty(); }
    /// True when the file holds a game that is not over: one to continue.
    bool unfinished() const { return game && !termpool::finished(*game); }
};

/// Reads the save at `path` (following a link to it) and replays it. A file that is not a
/// regular file, or larger than `max_save_bytes`, is not read (an error says so).
SaveContents read_save(const std::string& path);

} // namespace termpool
