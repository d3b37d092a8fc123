// A saved game played back: the Match replays the record up to any action, and each shot is
// shown as it was played. Space pauses, Left/Right step a shot.

#include <algorithm>
#include <string>

#include "tui/app.hpp"

namespace termpool::tui {

void App::start_replay(const GameRecord& record) {
    replaying_ = true;
    replay_record_ = record;
    entry_.player = 0;
    rewind_to(0);
}

void App::rewind_to(std::size_t action) {
    // Rebuild the match from the start without animation, up to (not including) `action`.
    next_action_ = std::min(action, replay_record_.actions.size());
    auto replayed = Match::replay(replay_record_, next_action_);
    if (Match* m = std::get_if<Match>(&replayed))
        match_ = std::move(*m);
    show_.stop(match_.game().balls());
    verdicts_.clear();
    mode_ = Mode::replay; // no aiming, no placing: the replay only shows
    message_ = "Replay (space pauses, Left/Right step a shot, x skips, q quits)";
}

void App::replay_step() {
    if (paused_ || mode_ == Mode::animating)
        return;
    const std::vector<RecordedAction>& actions = replay_record_.actions;
    while (next_action_ < actions.size()) {
        const RecordedAction& a = actions[next_action_++];
        if (a.kind != RecordedAction::Kind::shot) {
            match_.apply(a);
            show_.stop(match_.game().balls());
            continue;
        }
        const auto is_shot = [](const RecordedAction& r) {
            return r.kind == RecordedAction::Kind::shot;
        };
        const auto shot = std::count_if(actions.begin(), actions.begin() + next_action_, is_shot);
        const auto shots = std::count_if(actions.begin(), actions.end(), is_shot);
        play(a.strike, a.call);
        // The verdict line keeps the shot before's verdict while this one rolls.
        message_ = "Replay, shot " + std::to_string(shot) + " of " + std::to_string(shots) +
                   " (space pauses, Left/Right step, x skips, l log, q quits)";
        return;
    }
    message_ = "Replay ended: Left steps back, q quits";
    paused_ = true;
}

void App::handle_replay_key(const Input& in) {
    if (in.kind == Input::Kind::mouse) {
        if (in.clicked && mode_ == Mode::animating)
            show_.hurry();
        return;
    }
    if (in.text == "q") {
        running_ = false;
    } else if (in.text == "?") {
        help_ = true;
        help_page_ = 0;
    } else if (in.text == " ") {
        paused_ = !paused_;
    } else if (in.text == "x" && mode_ == Mode::animating) {
        show_.hurry();
    } else if (in.key == key_left || in.key == key_right) {
        // Step a whole shot: back to the start of the previous one, or on past the next.
        const std::vector<RecordedAction>& actions = replay_record_.actions;
        std::size_t shot_starts = 0, target = 0;
        for (std::size_t i = 0; i < actions.size(); ++i) {
            if (actions[i].kind != RecordedAction::Kind::shot)
                continue;
            if (i + 1 <= next_action_ - (mode_ == Mode::animating ? 1 : 0))
                shot_starts = i + 1;
        }
        if (in.key == key_left) {
            target = 0;
            for (std::size_t i = 0; i + 1 < shot_starts; ++i)
                if (actions[i].kind == RecordedAction::Kind::shot)
                    target = i + 1;
        } else {
            target = shot_starts;
            for (std::size_t i = shot_starts; i < actions.size(); ++i)
                if (actions[i].kind == RecordedAction::Kind::shot) {
                    target = i + 1;
                    break;
                }
        }
        rewind_to(target);
        paused_ = true;
    }
}

} // namespace termpool::tui
