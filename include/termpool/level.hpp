#pragma once
/// \file
/// How well a computer player plays. Its own header, so that what only names a level (a game
/// record's seats, the game's options) needs not the computer's search.

#include <optional>
#include <string>
#include <termpool/enum_names.hpp>

namespace termpool {

/// How well the computer plays: execution noise and how much it searches.
enum class Level {
    easy,   ///< noise x4, no spin, fewest candidates
    medium, ///< noise x2
    hard,   ///< noise x1 (the computer-pool tournament reference)
    pro,    ///< noise x0.5, the most candidates
};

/// The levels' names, as the command line and a record's seats give them.
inline constexpr NameRow<Level> level_names[] = {
    {Level::easy, "easy"},
    {Level::medium, "medium"},
    {Level::hard, "hard"},
    {Level::pro, "pro"},
};
static_assert(names_in_order(level_names));

/// "easy", "medium", "hard" or "pro".
const char* level_name(Level level);
/// Parses a level name; nothing for an unknown one.
std::optional<Level> parse_level(const std::string& name);

} // namespace termpool
