#pragma once
/// \file
/// How much the aiming aid helps: a setting of the game, kept in its record so that both seats
/// of a table play with the same help and a resumed game keeps it.

#include <optional>
#include <string_view>
#include <termpool/enum_names.hpp>

namespace termpool {

/// How much the aiming aid shows, and where a turn's aim starts.
enum class Assist {
    guided,   ///< the aim starts at the easiest pot; the shot's lines run to rails and pockets
    standard, ///< the aim starts full on a legal ball; the object ball's line is short
    pro,      ///< the aim starts full on a legal ball; the cue ball's line to its first contact
};

/// The assists' names, as the command line and a record give them.
inline constexpr NameRow<Assist> assist_names[] = {
    {Assist::guided, "guided"},
    {Assist::standard, "standard"},
    {Assist::pro, "pro"},
};
static_assert(names_in_order(assist_names));

/// "guided", "standard" or "pro".
const char* assist_name(Assist assist);
/// Parses an assist name; nothing for an unknown one.
std::optional<Assist> parse_assist(std::string_view name);

} // namespace termpool
