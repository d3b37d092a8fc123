#include "tui/local_driver.hpp"

#include <termpool/game_registry.hpp>
#include <termpool/race.hpp>
#include <termpool/record.hpp>

#include "files/atomic_file.hpp"
#include "player/stats_file.hpp"
#include "player/stats_summary.hpp"
#include "tui/table_news.hpp"

namespace termpool::tui {
namespace {

// Two computers in a race rack the next rack by themselves, after this look at the score.
constexpr auto computers_look = std::chrono::seconds(4);

// The computer's decision as the action it will be.
RecordedAction action_of(const ComputerMove& move) {
    RecordedAction action;
    switch (move.kind) {
    case Pending::place:
        action.kind = RecordedAction::Kind::place;
        action.place = move.spot;
        break;
    case Pending::choose:
        action.kind = RecordedAction::Kind::choose;
        action.choice = move.choice;
        break;
    default:
        action.kind = RecordedAction::Kind::shot;
        action.strike = move.shot.strike;
        action.call = move.shot.call;
        break;
    }
    return action;
}

} // namespace

Match first_match(const GameOptions& options, std::uint64_t seed) {
    GameRecord header;
    header.setup = options.setup;
    header.seed = seed;
    for (int p = 0; p < 2; ++p)
        if (options.names[p])
            header.names[p] = *options.names[p];
    header.race_to = options.race_to;
    header.break_rule = options.break_rule;
    header.assist = options.assist;
    auto started = Match::start(header, seed + 1);
    if (Match* match = std::get_if<Match>(&started))
        return std::move(*match);
    // The options come checked; should the match still refuse them, the defaults play.
    GameRecord defaults;
    defaults.setup.game = options.setup.game;
    defaults.seed = seed;
    return std::get<Match>(Match::start(defaults, seed + 1));
}

LocalDriver::LocalDriver(const GameOptions& options, std::uint64_t seed)
    : options_(options), seed_(seed + 1), match_(first_match(options, seed)) {}

void LocalDriver::resume(Match match) {
    match_ = std::move(match);
    // The computers take up their seats with new streams, as a new game's do.
    match_.reseed_computers(seed_);
    upcoming_.reset();
}

std::optional<TableNews> LocalDriver::submit(const RecordedAction& action, std::string& refusal) {
    return apply(action, refusal);
}

std::optional<TableNews> LocalDriver::apply(const RecordedAction& action, std::string& refusal) {
    upcoming_.reset();
    std::optional<TableNews> news;
    MatchError error = MatchError::none;
    if (action.kind == RecordedAction::Kind::rack) {
        // The rack's seed is the match's to draw: a rack action names only the breaker.
        error = match_.next_rack(action.breaker);
        if (error == MatchError::none) {
            news.emplace();
            news->action = action;
            news->actor = action.breaker;
            news->words = rack_words(match_, action.breaker, may_act());
        }
    } else {
        news = take_action(match_, action, error);
    }
    if (!news) {
        refusal = match_error_text(error);
        return std::nullopt;
    }
    save();
    if (match_.game().winner() != 0 && match_.score().match_winner() != 0 &&
        action.kind != RecordedAction::Kind::rack) {
        const std::string notice = keep_figures();
        if (!notice.empty())
            news->words += " (" + notice + ")";
    }
    return news;
}

const Upcoming* LocalDriver::upcoming(Clock::time_point now) {
    if (upcoming_)
        return &*upcoming_;
    const PendingAction pending = match_.pending();
    if (pending.kind == Pending::next_rack && match_.seat(1).computer && match_.seat(2).computer) {
        if (!rack_over_seen_) {
            rack_over_seen_ = true;
            rack_over_at_ = now;
        }
        if (now - rack_over_at_ < computers_look)
            return nullptr;
        RecordedAction rack;
        rack.kind = RecordedAction::Kind::rack;
        rack.breaker = match_.next_breaker();
        upcoming_ = Upcoming{rack, false, false};
        return &*upcoming_;
    }
    rack_over_seen_ = false;
    if (computer_refused_ || !match_.computer_to_act())
        return nullptr;
    const std::optional<ComputerMove> move = match_.computer_move();
    if (!move)
        return nullptr;
    upcoming_ = Upcoming{action_of(*move), true, false};
    return &*upcoming_;
}

std::optional<TableNews> LocalDriver::take() {
    if (!upcoming_)
        return std::nullopt;
    const RecordedAction action = upcoming_->action;
    std::string refusal;
    std::optional<TableNews> news = apply(action, refusal);
    if (!news) {
        // Asking again would bring the same move: say so once, and wait for the player to
        // leave (the game is saved as it stands).
        computer_refused_ = true;
        message_ = "The computer's move was refused (" + refusal + "); q quits, the game is saved";
    }
    return news;
}

bool LocalDriver::rematch(int breaker) {
    // The players keep their seats (and names) from the game before, the computers their
    // streams.
    match_ = std::move(match_).rematch(breaker, seed_++);
    upcoming_.reset();
    computer_refused_ = false;
    return true;
}

MatchError LocalDriver::rename(int player, const std::string& name) {
    return match_.rename(player, name);
}

MatchError LocalDriver::seat_computer(int player, Level level) {
    const MatchError error = match_.seat_computer(player, level);
    if (error != MatchError::none)
        return error;
    // Two computers (watching) are told apart by their seat.
    const std::string seat = options_.watch ? " " + std::to_string(player) : "";
    return match_.rename(player, "CPU" + seat + " (" + level_name(level) + ")");
}

MatchError LocalDriver::set_race(int race_to) {
    const MatchError error = match_.set_race(race_to);
    if (error == MatchError::none)
        options_.race_to = race_to;
    return error;
}

void LocalDriver::save() {
    // The record is the whole game: rewritten after every action, so a dropped connection
    // loses at most the shot in flight. A failure stays on the message line until a save works
    // again: the player must not miss that the game is not being kept.
    save_problem_.clear();
    write_atomically(options_.save_path, format_record(match_.record()), save_problem_);
}

std::string LocalDriver::keep_figures() {
    // Once per finished game or match; computers are kept under their names ("CPU (hard)").
    const PlayerStats figures[2] = {match_.tally().of(1), match_.tally().of(2)};
    return save_game_stats(stats_path(), match_.record().names, match_.tally().game(), figures);
}

std::string LocalDriver::game_over_text(const std::string& told) const {
    const MatchState& s = match_.score();
    const std::string& one = match_.name(1);
    const std::string& two = match_.name(2);
    const std::string summary = "\n\n" + stats_summary(match_.record().names, match_.tally());
    // Snooker says frames: the next is a frame, a match of them best of N.
    const GameRow& row = game_row(match_.game().type());
    const bool frames = row.scoring == Scoring::points;
    if (!s.is_race())
        return told + summary + "\n\nr  " + row.words.rematch + "\nn  " + row.words.new_game +
               "\nq  quit";
    const std::string race =
        (frames ? "Best of " + std::to_string(best_of_for_race(s.race_to)) + " frames"
                : "Race to " + std::to_string(s.race_to)) +
        ": " + one + " " + std::to_string(s.racks_won[0]) + ", " + two + " " +
        std::to_string(s.racks_won[1]);
    if (const int winner = s.match_winner())
        return told + "\n\n" + match_.name(winner) + " wins the match\n" + race + summary +
               "\n\nr  " + row.words.match_rematch + "\nn  new match\nq  quit";
    return told + "\n\n" + race + summary + "\n\nEnter  next " + row.words.unit + " (" +
           match_.name(match_.next_breaker()) + " " + row.words.breaks +
           ")\nq      quit (the match is saved)";
}

} // namespace termpool::tui
