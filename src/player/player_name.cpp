// clean_player_name: trim, refuse what a terminal cannot show safely, cut to the column limit.

#include "player/player_name.hpp"

#include <termpool/name_characters.hpp>
#include <termpool/record.hpp>
#include <termpool/text_width.hpp>

namespace termpool {
namespace {

std::string_view trim_spaces(std::string_view s) {
    while (!s.empty() && s.front() == ' ')
        s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ')
        s.remove_suffix(1);
    return s;
}

} // namespace

std::optional<std::string> clean_player_name(std::string_view input, std::string& error) {
    error.clear();
    if (trim_spaces(input).empty())
        return std::nullopt; // blank: the current name stays
    // Control characters would move the cursor or change the terminal's state when the name
    // is drawn; invisible and direction-changing ones make two names look alike, or turn the
    // line they are shown on around.
    if (auto problem = name_characters_problem(input)) {
        error = std::move(*problem);
        return std::nullopt;
    }
    // Cutting can leave a space at the end ("ab cd" cut after "ab "), so trim after it too.
    std::string cut = truncate_to_width(trim_spaces(input), max_name_columns);
    // Zero-width marks take no columns but bytes: the record holds at most so many.
    if (cut.size() > max_player_name_bytes) {
        std::size_t end = max_player_name_bytes;
        while (end > 0 && (static_cast<unsigned char>(cut[end]) & 0xC0) == 0x80)
            --end;
        cut.resize(end);
    }
    const std::string_view name = trim_spaces(cut);
    if (name.empty())
        return std::nullopt;
    // Cutting can leave only what does not show (wide spaces before the first letter).
    if (auto problem = name_characters_problem(name)) {
        error = std::move(*problem);
        return std::nullopt;
    }
    return std::string(name);
}

bool name_has_room(std::string_view text, std::string_view typed) {
    const std::string name = std::string(text) + std::string(typed);
    return display_width(trim_spaces(name)) <= max_name_columns;
}

} // namespace termpool
