#pragma once
// The rules for a player's name typed at the name prompt.

#include <optional>
#include <string>
#include <string_view>
#include <termpool/name_characters.hpp> // max_name_columns

namespace termpool {

/// The name to use for `input`: spaces trimmed at both ends, cut to `max_name_columns` columns
/// between characters. Returns nothing with an empty `error` when the input is blank (keep the
/// current name), and nothing with a message in `error` when it holds invalid UTF-8, a control
/// character or an invisible or direction-changing one (`name_characters_problem`).
std::optional<std::string> clean_player_name(std::string_view input, std::string& error);

/// Whether `typed` may follow `text` at a name prompt: the name it makes, spaces trimmed, stays
/// within `max_name_columns`, so that the prompt stops taking keys where the name would be cut.
bool name_has_room(std::string_view text, std::string_view typed);

} // namespace termpool
