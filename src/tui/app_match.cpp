// Matches and what a game leaves behind: the racks of a race, the figures at the end of a game
// and in the stats file, and a saved game taken up again.

#include <string>

#include "tui/app.hpp"
#include "tui/stats_file.hpp"
#include "tui/stats_summary.hpp"

namespace termpool::tui {

void App::next_rack() {
    const int breaker = match_.next_breaker(rack_breaker_, game_.winner());
    const RecordedAction rack = rack_action(record_, rack_ + 1, breaker);
    record_.actions.push_back(rack);
    start_rack(rack);
    save();
    message_ = "Rack " + std::to_string(rack_) + ": " + names_[breaker - 1] +
               " breaks: place the cue ball in the kitchen";
    start_turn();
}

void App::start_rack(const RecordedAction& rack) {
    ++rack_;
    game_ = make_game(record_.setup, rack.breaker, rack.seed);
    rack_breaker_ = rack.breaker;
    shown_balls_ = game_.balls();
}

void App::save_stats() {
    // Once per finished game or match; computers are kept under their names ("CPU (hard)").
    const PlayerStats figures[2] = {tally_.of(1), tally_.of(2)};
    const std::string notice = save_game_stats(stats_path(), names_, figures);
    if (!notice.empty())
        message_ += " (" + notice + ")";
}

std::string App::game_over_text() const {
    const auto score = [&] {
        return names_[0] + " " + std::to_string(match_.racks_won[0]) + ", " + names_[1] + " " +
               std::to_string(match_.racks_won[1]);
    };
    const PlayerStats figures[2] = {tally_.of(1), tally_.of(2)};
    const std::string summary = "\n\n" + stats_summary(names_, figures);
    if (!match_.is_race())
        return message_ + summary + "\n\nr  rematch (loser breaks)\nn  new game\nq  quit";
    const std::string race = "Race to " + std::to_string(match_.race_to) + ": " + score();
    if (const int winner = match_.match_winner())
        return message_ + "\n\n" + names_[winner - 1] + " wins the match\n" + race + summary +
               "\n\nr  rematch (loser breaks)\nn  new match\nq  quit";
    const int breaker = match_.next_breaker(rack_breaker_, game_.winner());
    return message_ + "\n\n" + race + summary + "\n\nEnter  next rack (" + names_[breaker - 1] +
           " breaks)\nq      quit (the match is saved)";
}

bool App::computers_watched_rack_over() const {
    // Two computers in a race go on by themselves, after a look at the score.
    return mode_ == Mode::game_over && computers_[0] && computers_[1] && match_.is_race() &&
           match_.match_winner() == 0 && Clock::now() - game_over_at_ > std::chrono::seconds(4);
}

void App::resume(const GameRecord& record, ResumedGame state) {
    record_ = record;
    for (int p = 0; p < 2; ++p) {
        names_[p] = record.names[p];
        if (record.computers[p])
            computers_[p].emplace(*record.computers[p], seed_ + static_cast<std::uint64_t>(p + 1));
        else
            computers_[p].reset();
    }
    game_ = std::move(state.match.game);
    match_ = state.match.score;
    rack_ = state.match.rack;
    rack_breaker_ = state.match.rack_breaker;
    tally_ = state.tally;
    entry_player_ = 0;
    // Where the game stands comes first here: the player needs it before any news.
    message_ = "Game resumed: " + resumed_words();
    for (const std::string& n : options_.notices)
        message_ += "; " + n;
    start_turn();
}

std::string App::resumed_words() const {
    if (const int winner = game_.winner()) {
        if (match_.is_race() && match_.match_winner() == 0)
            return names_[winner - 1] + " won rack " + std::to_string(rack_);
        return names_[winner - 1] + " won";
    }
    if (const int chooser = game_.chooser())
        return names_[chooser - 1] + " to choose";
    return names_[game_.shooter() - 1] + " to play";
}

} // namespace termpool::tui
