#include "player/config.hpp"

#include "support/text_lines.hpp"

#include "files/xdg_dir.hpp"
#include "player/player_name.hpp"

namespace termpool {
namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

} // namespace

std::string config_path() {
    return xdg_dir("XDG_CONFIG_HOME", ".config") + "/termpool/config";
}

std::optional<std::string> apply_config(std::string_view text, GameOptions& o,
                                        std::vector<std::string>& warnings) {
    for (const TextLine& text_line : text_lines(text)) {
        const int number = text_line.number;
        const std::string_view line = trim(strip_comment(text_line.text));
        if (line.empty())
            continue;
        const std::size_t eq = line.find('=');
        auto fail = [&](const std::string& what) { return std::to_string(number) + ": " + what; };
        if (eq == std::string_view::npos)
            return fail("expected 'key = value'");
        const std::string key(trim(line.substr(0, eq)));
        const std::string value(trim(line.substr(eq + 1)));
        if (key == "player1" || key == "player2") {
            std::string why;
            const auto name = clean_player_name(value, why);
            if (!why.empty())
                return fail(key + ": " + why);
            if (name)
                o.names[key == "player1" ? 0 : 1] = name;
        } else if (key == "game") {
            const auto g = parse_game_type(value);
            if (!g)
                return fail("unknown game '" + value + "' (8ball, 8ball-bar, 9ball or 10ball)");
            o.setup.game = *g;
        } else if (key == "table") {
            const std::optional<TableSize> size = parse_table_size(value);
            if (!size)
                return fail("unknown table '" + value + "' (7ft, 8ft, 9ft or snooker)");
            o.setup.table = *size;
        } else if (key == "race") {
            const auto n = parse_race_to(value);
            if (!n)
                return fail("race is a number of racks from 1 to " + std::to_string(max_race_to) +
                            ", not '" + value + "'");
            o.race_to = *n;
        } else if (key == "breaks") {
            const auto rule = parse_break_rule(value);
            if (!rule)
                return fail("breaks is alternate or winner, not '" + value + "'");
            o.break_rule = *rule;
        } else if (key == "power-mode") {
            if (value != "distance" && value != "timed")
                return fail("power-mode is distance or timed, not '" + value + "'");
            o.timed_power = value == "timed";
        } else if (key == "aim-aid") {
            if (value != "on" && value != "off")
                return fail("aim-aid is on or off, not '" + value + "'");
            o.aim_aid = value == "on";
        } else if (key == "assist") {
            const auto assist = parse_assist(value);
            if (!assist)
                return fail("assist is guided, standard or pro, not '" + value + "'");
            o.assist = *assist;
        } else if (key == "level") {
            const auto level = parse_level(value);
            if (!level)
                return fail("unknown level '" + value + "' (easy, medium, hard or pro)");
            o.default_level = *level;
        } else {
            warnings.push_back(config_path() + ":" + std::to_string(number) + ": unknown key '" +
                               key + "' ignored");
        }
    }
    return std::nullopt;
}

} // namespace termpool
