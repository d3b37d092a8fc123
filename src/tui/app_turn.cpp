// A turn at the table: the match says what it waits for and the App goes into that mode;
// placing, shooting and choosing become the match's actions, each saved as it is taken, and a
// shot is shown rolling before its verdict.

#include <algorithm>
#include <optional>
#include <string>
#include <termpool/setup.hpp>
#include <termpool/snooker_layout.hpp>
#include <vector>

#include "player/save_file.hpp"
#include "tui/app.hpp"
#include "tui/cue_ball_spot.hpp"
#include "tui/messages.hpp"
#include "tui/nomination.hpp"

namespace termpool::tui {

void App::begin() {
    message_ = practice_
                   ? "Practice: no referee. m moves a ball, r takes a shot again, t racks again"
                   : breaks_words(game().shooter());
    // News from before the game (a config warning, where it is saved) leads the first line.
    for (auto n = options_.notices.rbegin(); n != options_.notices.rend(); ++n)
        message_ = *n + "; " + message_;
    start_turn();
}

void App::start_turn() {
    show_.stop(game().balls());
    aim().new_turn();
    pacing_.stop();
    const PendingAction pending =
        practice_ ? PendingAction{Pending::shoot, 1, BallInHand::none, {}} : match_.pending();
    if (pending.kind == Pending::over || pending.kind == Pending::next_rack) {
        mode_ = Mode::game_over;
        game_over_at_ = Clock::now();
        return;
    }
    if (pending.kind == Pending::choose) {
        mode_ = Mode::choosing;
        return;
    }
    if (pending.kind == Pending::place) {
        const Game& g = game();
        const Ball* cue = nullptr;
        for (const Ball& b : g.balls())
            if (b.id == 0)
                cue = &b;
        const bool must_move =
            !cue || cue->state == MotionState::pocketed || !g.legal_placement(cue->position);
        warn_of_third_foul();
        mode_ = Mode::placing;
        place_ = must_move ? first_cue_ball_spot(g, table_.head_spot()) : cue->position;
        return;
    }
    start_aiming();
}

void App::warn_of_third_foul() {
    // WPA 9-ball and 10-ball: a player on two fouls must be told before the shot that a third
    // loses.
    const Game& g = game();
    if (is_rotation_game(g.type()) && g.consecutive_fouls(g.shooter()) >= 2)
        message_ += (message_.empty() ? "" : "; ") + name(g.shooter()) +
                    " is on two fouls: a third in a row loses the game";
}

void App::start_aiming() {
    mode_ = Mode::aiming;
    aim().set_break(game().is_break());
    aim_at_easiest();
    warn_of_third_foul();
    const std::string& who = name(game().shooter());
    // Someone else's turn (the computer's, or another terminal's in the hall): no how-to.
    const bool computer = computer_to_act() || (in_hall() && !hall_seat_to_act());
    if (game().push_out_allowed()) {
        const std::string hint = "u declares a push-out";
        message_ = !message_.empty()   ? message_ + "; " + hint
                   : verdicts_.empty() ? who + ": aim and shoot, or " + hint
                                       : hint;
    } else if (message_.empty() && verdicts_.empty() && !computer) {
        // Short enough for the smallest panel; the help has the rest.
        message_ = who + ": aim (" + (term_.caps().mouse ? "mouse, " : "") +
                   "Left/Right), Space shoots" + (practice_ ? "; m moves a ball" : "");
    }
    if (snooker_play() && game().nomination_owed() && !computer)
        message_ += (message_.empty() ? who + ": " : "; ") +
                    std::string(game().snooker().free_ball ? "a free ball: 2-7 nominates it"
                                                           : "2-7 nominates a colour");
    // The proposed aim cannot reach the ball straight: say so before Space is pressed.
    if (aim().target_line != TargetLine::straight && !computer)
        message_ += (message_.empty() ? "" : "; ") +
                    std::string(aim().target_line == TargetLine::kick
                                    ? "no straight line to a legal ball: a kick off one rail"
                                    : "no clear line to a legal ball");
}

std::string App::breaks_words(int breaker) const {
    return name(breaker) + " breaks: place the cue ball " +
           ball_in_hand_words(game().type() == GameType::snooker ? BallInHand::d
                                                                 : BallInHand::kitchen);
}

void App::ask_concede() {
    // Only the player to act concedes, and only at this terminal's seat in the hall.
    if (computer_to_act() || (in_hall() && !hall_seat_to_act()) || game().winner() != 0)
        return;
    confirm_concede_ = true;
}

void App::concede() {
    const int who = match_.to_act();
    if (in_hall()) {
        RecordedAction action;
        action.kind = RecordedAction::Kind::choose;
        action.choice = Choice::concede;
        send_to_hall(action);
        return;
    }
    if (match_.concede(who) != MatchError::none)
        return;
    message_.clear();
    tell(name(who) + " concedes the frame \u2014 " + name(3 - who) + " wins it");
    save();
    if (match_.score().match_winner() != 0 && !replaying_)
        save_stats();
    start_turn();
}

bool App::try_place(Vec2 spot) {
    if (in_hall()) {
        // The server places it; the aim starts when its word comes back.
        if (!game().legal_placement(spot)) {
            message_ = "The cue ball cannot go there: " + placement_problem(game(), spot);
            return false;
        }
        RecordedAction action;
        action.kind = RecordedAction::Kind::place;
        action.place = spot;
        player_acts();
        return send_to_hall(action);
    }
    if (!place(spot)) {
        message_ = "The cue ball cannot go there: " + placement_problem(game(), spot);
        return false;
    }
    player_acts();
    message_.clear();
    start_aiming();
    return true;
}

void App::shoot() {
    const auto now = Clock::now();
    const Strike strike = aim().strike(game().is_break(), now);
    // A cue the simulator cannot play (a jump shot, which it does not model) is not shot: the
    // player adjusts it.
    if (const std::optional<std::string> problem = strike_problem(strike, params_)) {
        message_ = "Not played: " + *problem;
        return;
    }
    const double power = aim().current_power(now);
    ShotCall call =
        game().call_as_taken(aim().call([this](int ball) { return calls_pocket(ball); }));
    if (snooker_play()) {
        // The nomination the player named; without one the referee takes the ball hit first,
        // the aimed ball the panel proposed.
        call.call = nomination_call(game(), aim());
    }
    aim().power = power;
    player_acts();
    if (in_hall()) {
        RecordedAction action;
        action.kind = RecordedAction::Kind::shot;
        action.strike = strike;
        action.call = call;
        send_to_hall(action);
        return;
    }
    play(strike, call);
}

bool App::place(Vec2 spot) {
    if (match_.place(match_.to_act(), spot) != MatchError::none)
        return false;
    save();
    return true;
}

void App::choose(Choice choice) {
    if (match_.choose(match_.to_act(), choice) == MatchError::none)
        save();
}

void App::save() {
    // A replay shows a game, practice has none: neither writes over a saved game. The hall's
    // server keeps its tables itself.
    if (replaying_ || practice_ || in_hall())
        return;
    // The record is the whole game: rewritten after every action, so a dropped connection
    // loses at most the shot in flight. A failure stays on the message line until a save works
    // again: other messages come and go, and the player must not miss that the game is not
    // being kept.
    save_problem_.clear();
    write_atomically(options_.save_path, format_record(match_.record()), save_problem_);
}

void App::play(const Strike& strike, const ShotCall& call) {
    last_strike_ = strike;
    Trajectory trajectory(params_, game().balls().size());
    if (practice_) {
        PlayedShot shot; // no referee: the simulation alone
        shot.shooter = game().shooter();
        shot.result = practice_->shoot(strike, &trajectory);
        show_shot(std::move(shot), std::move(trajectory), score(), std::nullopt);
        return;
    }
    Game before = match_.game();
    const MatchState score = match_.score();
    auto played = match_.shoot(match_.to_act(), strike, call, &trajectory);
    if (const MatchError* refused = std::get_if<MatchError>(&played)) {
        message_ = std::string("The shot was refused: ") + match_error_text(*refused);
        return;
    }
    show_shot(std::move(std::get<PlayedShot>(played)), std::move(trajectory), score,
              std::move(before));
}

void App::show_shot(PlayedShot shot, Trajectory trajectory, MatchState score_before,
                    std::optional<Game> before) {
    // The match has judged the shot already; the game as it was shows until the balls stop.
    const int shooter = shot.shooter;
    show_.start(std::move(shot), std::move(trajectory), std::move(before), score_before,
                Clock::now());
    mode_ = Mode::animating;
    message_ = name(shooter) + " shoots";
}

void App::after_shot() {
    show_.stop(show_.balls());
    if (practice_) {
        practice_shot_done();
        return;
    }
    message_.clear();
    const PlayedShot& shot = show_.shot();
    tell(verdict_message(shot.verdict, shot.shooter, match_.record().names));
    save();
    if (shot.verdict.winner != 0 && match_.score().match_winner() != 0 && !replaying_ && !in_hall())
        save_stats();
    start_turn();
    if (replaying_)
        mode_ = Mode::replay; // the replay shows the next action itself
}

} // namespace termpool::tui
