// Matches and what a game leaves behind: new games and rematches, the racks of a race, the
// computer's turns shown at a player's pace, the figures at the end of a game and in the
// stats file, and a saved game taken up again.

#include <string>
#include <termpool/race.hpp>

#include "player/stats_file.hpp"
#include "player/stats_summary.hpp"
#include "tui/app.hpp"
#include "tui/messages.hpp"

namespace termpool::tui {

void App::new_game(int breaker) {
    // The players keep their seats (and names) from the game before, the computers their
    // streams.
    match_ = std::move(match_).rematch(breaker, seed_++);
    show_.stop(match_.game().balls());
    verdicts_.clear();
    message_ = breaks_words(breaker);
}

void App::next_rack() {
    const int breaker = match_.next_breaker();
    if (in_hall()) {
        RecordedAction action;
        action.kind = RecordedAction::Kind::rack;
        action.breaker = breaker;
        send_to_hall(action);
        return;
    }
    if (match_.next_rack(breaker) != MatchError::none)
        return;
    show_.stop(match_.game().balls());
    save();
    message_ = (snooker_play() ? "Frame " : "Rack ") + std::to_string(match_.rack()) + ": " +
               breaks_words(breaker);
    start_turn();
}

void App::save_stats() {
    // Once per finished game or match; computers are kept under their names ("CPU (hard)").
    const PlayerStats figures[2] = {match_.tally().of(1), match_.tally().of(2)};
    const std::string notice = save_game_stats(stats_path(), match_.record().names, figures);
    if (!notice.empty())
        message_ += " (" + notice + ")";
}

std::string App::game_over_text() const {
    if (in_hall())
        return hall_game_over_text();
    const MatchState& s = match_.score();
    const auto score_words = [&] {
        return name(1) + " " + std::to_string(s.racks_won[0]) + ", " + name(2) + " " +
               std::to_string(s.racks_won[1]);
    };
    const PlayerStats figures[2] = {match_.tally().of(1), match_.tally().of(2)};
    const std::string summary = "\n\n" + stats_summary(match_.record().names, figures);
    if (!s.is_race())
        return said() + summary + "\n\nr  rematch (loser breaks)\nn  new game\nq  quit";
    // Snooker says a match of frames as best of N.
    const bool frames = snooker_play();
    const std::string race =
        (frames ? "Best of " + std::to_string(best_of_for_race(s.race_to)) + " frames"
                : "Race to " + std::to_string(s.race_to)) +
        ": " + score_words();
    if (const int winner = s.match_winner())
        return said() + "\n\n" + name(winner) + " wins the match\n" + race + summary +
               "\n\nr  rematch (loser breaks)\nn  new match\nq  quit";
    return said() + "\n\n" + race + summary + "\n\nEnter  next " + (frames ? "frame (" : "rack (") +
           name(match_.next_breaker()) + " breaks)\nq      quit (the match is saved)";
}

bool App::computer_to_act() const {
    // In the hall the server plays the computer's seats.
    if (practice_ || replaying_ || in_hall() || mode_ == Mode::names || mode_ == Mode::animating ||
        mode_ == Mode::game_over)
        return false;
    return match_.computer_to_act();
}

bool App::computers_watched_rack_over() const {
    // Two computers in a race go on by themselves, after a look at the score.
    return mode_ == Mode::game_over && !in_hall() && match_.seat(1).computer &&
           match_.seat(2).computer && match_.pending().kind == Pending::next_rack &&
           Clock::now() - game_over_at_ > std::chrono::seconds(4);
}

void App::computer_turn() {
    // The computer's turn is shown like a player's: it places the cue ball, turns the cue to
    // its aim, fills the power bar, then shoots.
    const Clock::time_point now = Clock::now();
    if (!pacing_.showing()) {
        const std::optional<ComputerMove> move = match_.computer_move();
        if (!move)
            return;
        pacing_.start(*move, aim().aim_deg, now);
        if (move->kind == Pending::place)
            place_ = move->spot;
        return;
    }
    const ComputerMove move = pacing_.move();
    if (move.kind == Pending::choose) {
        if (!pacing_.due(now))
            return;
        pacing_.stop();
        if (move.choice == Choice::concede) {
            concede();
            return;
        }
        const std::string who = name(match_.to_act());
        const std::string words =
            choice_words(move.choice, game().type(), game().free_ball_offered());
        choose(move.choice);
        message_.clear();
        tell(who + ": " + words);
        start_turn();
        return;
    }
    if (move.kind == Pending::place) {
        if (!pacing_.due(now))
            return;
        pacing_.stop();
        if (place(place_)) {
            message_.clear();
            start_aiming();
        }
        return;
    }
    if (!show_computer_aim(now))
        return;
    pacing_.stop();
    play(move.shot.strike, move.shot.call);
}

bool App::show_computer_aim(Clock::time_point now) {
    const ComputerMove& move = pacing_.move();
    const double t = pacing_.elapsed(now);
    aim().aim_deg = pacing_.aim_at(t);
    aim().side = move.shot.strike.side;
    aim().follow = move.shot.strike.follow;
    aim().elevation_deg = move.shot.strike.elevation_deg;
    aim().power = pacing_.power_at(t, game().is_break());
    // Snooker: the panel shows the computer's own nomination, if it names one.
    aim().nominated = move.shot.call.call.ball;
    aim().nomination_chosen = snooker_play() && game().nomination_owed() && aim().nominated != 0;
    update_preview();
    return pacing_.due(now);
}

void App::resume(Match match) {
    match_ = std::move(match);
    // The computers take up their seats with new streams, as a new game's do.
    match_.reseed_computers(seed_);
    entry_.player = 0;
    verdicts_.clear();
    // Where the game stands comes first here: the player needs it before any news.
    message_ = "Game resumed: " + resumed_words();
    for (const std::string& n : options_.notices)
        message_ += "; " + n;
    start_turn();
}

std::string App::resumed_words() const {
    const Game& g = match_.game();
    if (const int winner = g.winner()) {
        if (match_.pending().kind == Pending::next_rack)
            return name(winner) + " won rack " + std::to_string(match_.rack());
        return name(winner) + " won";
    }
    if (const int chooser = g.chooser())
        return name(chooser) + " to choose";
    return name(g.shooter()) + " to play";
}

} // namespace termpool::tui
