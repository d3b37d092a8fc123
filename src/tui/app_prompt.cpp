// The prompts: the players' names at the start (player 2 may be the computer), `n` to rename,
// and the race's length.

#include <string>

#include "player/player_name.hpp"
#include "tui/app.hpp"

namespace termpool::tui {

void App::handle_text_entry(const Input& in) {
    // Keys past the widest name are not taken: the name would be cut there.
    const auto room = [&](const std::string& typed) { return name_has_room(entry_.text, typed); };
    if (entry_.edit(in, room) || in.kind != Input::Kind::key)
        return;
    if (in.key == key_enter) {
        take_name();
    } else if (in.key == key_escape && !as<NamesMode>()) {
        entry_.player = 0;
        entry_.clear();
    }
}

void App::take_name() {
    // At the start, player 2 may be the computer: "computer" or "computer LEVEL".
    if (as<NamesMode>() != nullptr && entry_.player == 2 && entry_.text.starts_with("computer")) {
        const std::string rest = entry_.text.size() > 9 ? entry_.text.substr(9) : "";
        const auto level = rest.empty() ? std::optional<Level>(Level::medium) : parse_level(rest);
        if (!level) {
            entry_.error = "levels: easy, medium, hard, pro";
            return;
        }
        driver_->seat_computer(2, *level);
        entry_.clear();
        entry_.player = 0;
        ask_race();
        return;
    }
    std::string error;
    const auto name = clean_player_name(entry_.text, error);
    if (!error.empty()) {
        entry_.error = error;
        return;
    }
    if (name && driver_->rename(entry_.player, *name) != MatchError::none) {
        entry_.error = match_error_text(MatchError::bad_name);
        return;
    }
    entry_.clear();
    const bool starting = as<NamesMode>() != nullptr;
    if (starting && entry_.player == 1 && !options_.names[1] &&
        !driver_->match().seat(2).computer && driver_->referee()) {
        entry_.player = 2;
        return;
    }
    entry_.player = 0;
    if (starting)
        ask_race();
}

void App::ask_race() {
    // The last question of the name prompt: how long a match (practice has none).
    if (!driver_->referee()) {
        begin();
        return;
    }
    entry_.asking_race = true;
    entry_.clear();
}

void App::handle_race_entry(const Input& in) {
    // Up to two digits.
    const auto digit = [&](const std::string& typed) {
        return typed.size() == 1 && typed[0] >= '0' && typed[0] <= '9' && entry_.text.size() < 2;
    };
    if (entry_.edit(in, digit) || in.kind != Input::Kind::key)
        return;
    if (in.key != key_enter && in.key != key_escape)
        return;
    if (in.key != key_escape && !entry_.text.empty()) {
        // Snooker asks for the frames of the match, best of N.
        const bool frames = snooker_play();
        const std::optional<int> best_of = frames ? parse_best_of(entry_.text) : std::nullopt;
        const std::optional<int> race =
            frames ? (best_of ? std::optional<int>(race_for_best_of(*best_of)) : std::nullopt)
                   : parse_race_to(entry_.text);
        if (!race || driver_->set_race(*race) != MatchError::none) {
            entry_.error = frames ? "best of an odd number of frames: 1, 3, 5, ..."
                                  : "a race is 1 to " + std::to_string(max_race_to) + " racks";
            return;
        }
        options_.race_to = *race;
    }
    entry_.asking_race = false;
    entry_.clear();
    begin();
}

} // namespace termpool::tui
