#pragma once
/// \file
/// A player's figures for a game (and, added up, for all their games of one game type). Pool
/// (8-ball, 9-ball, 10-ball) keeps racks won, balls potted, pot success, fouls, break-and-runs
/// and the longest run; snooker keeps frames won, points, pot success, fouls, the highest break
/// and the centuries. A StatsTally hears the shots of a game as they are judged and keeps both
/// players' figures; it knows nothing of files or screens.
///
/// The figures, precisely:
/// - a *visit* is a player's stay at the table: it starts with their first shot after the
///   opponent's (or with a break) and ends with the shot that gives the table away (the
///   verdict's next shooter is the other player, the shot fouls, or the rack ends). A
///   push-out ends a visit too: the opponent decides what happens next.
/// - a shot is *legal* when it neither fouls nor loses the rack.
/// - *balls potted*: object balls pocketed on the player's legal shots, breaks included,
///   less those the rules put back on the table (a 9 on a push-out, an 8 on an 8-ball
///   break that does not win).
/// - a *pot attempt* is any shot but a break, a called safety or a push-out; it *succeeds*
///   when it is legal, pockets at least one object ball and the shooter keeps the table (or
///   wins the rack with it).
/// - *longest run*: most balls potted in one visit.
/// - a *break-and-run*: the player won the rack in the visit that began with their break,
///   so the opponent played no shot after that break (a re-break starts the count again). An
///   8 or 9 on the break that wins the rack counts.
/// - a rack is *played* by both players once it has a winner; re-racks (an illegal break, a
///   stalemate) are part of the same rack.
///
/// Snooker counts frames where pool counts racks, and differs in these:
/// - *balls potted*: every ball pocketed on a shot without a foul, colours that are re-spotted
///   included (they were potted and scored).
/// - *points*: the player's frame scores added up: the points of their pots and the penalties
///   of the opponent's fouls.
/// - a *break* is the points a player scores in one visit (the referee's break: a visit ends
///   with a shot that scores nothing or fouls, and at a re-spotted black); the *highest break*
///   is the best of them, a *century* a break of 100 or more.
/// - longest run and break-and-runs are not kept.

#include <array>
#include <optional>
#include <termpool/game_registry.hpp>
#include <termpool/record.hpp>
#include <termpool/rules.hpp>
#include <variant>

namespace termpool {

/// The figures `type` keeps: its registry row's (`GameRow::stats`).
StatsKind stats_kind(GameType type);

/// One player's figures; all counts start at zero. Which of them a game keeps depends on its
/// StatsKind (the others stay zero).
struct PlayerStats {
    int racks_won = 0;      ///< racks won (snooker: frames)
    int racks_played = 0;   ///< racks finished, won or lost (snooker: frames)
    int shots = 0;          ///< shots played, breaks included
    int pot_attempts = 0;   ///< shots that tried to pot (see the file comment)
    int pots_made = 0;      ///< pot attempts that succeeded
    int balls_potted = 0;   ///< object balls potted on legal shots
    int fouls = 0;          ///< shots with a foul
    int break_and_runs = 0; ///< racks won from the player's own break without a miss
    int longest_run = 0;    ///< most balls potted in one visit
    int points = 0;         ///< snooker: frame scores added up
    int highest_break = 0;  ///< snooker: most points in one visit
    int centuries = 0;      ///< snooker: breaks of 100 points or more

    /// Adds the counts of `more` (the longest run and the highest break are the larger of the
    /// two); a count stops at the largest int rather than overflow.
    void add(const PlayerStats& more);

    /// Field by field.
    friend bool operator==(const PlayerStats&, const PlayerStats&) = default;
};

/// Pots made over pot attempts, 0..1; nothing before the first attempt.
std::optional<double> pot_success(const PlayerStats& stats);

/// Both players' figures as the shots of a game are judged.
class StatsTally {
public:
    /// The tally of a game of `game`, which decides what it counts (see stats_kind).
    explicit StatsTally(GameType game) : game_(game), kind_(stats_kind(game)) {}

    /// Hears one judged shot: `shooter` (1 or 2) played it, `was_break` when it was a break,
    /// `call` as the game took it (push_out only when a push-out was allowed) and `verdict`
    /// as Game::apply returned it. A verdict with a winner ends the rack.
    void on_shot(int shooter, bool was_break, const ShotCall& call, const Verdict& verdict);
    /// Hears a rack that ended without a shot, a snooker frame conceded: `winner` (1 or 2) won
    /// it, and the visit at the table is over.
    void on_conceded(int winner);

    /// The figures of `player` (1 or 2) so far.
    const PlayerStats& of(int player) const { return stats_[player == 2 ? 1 : 0]; }

    /// Both players' figures, player 1 first.
    const std::array<PlayerStats, 2>& both() const { return stats_; }

    /// The game type tallied.
    GameType game() const { return game_; }
    /// What it counts.
    StatsKind kind() const { return kind_; }

    /// Snooker: the score of `player` (1 or 2) in the frame being played, or in the last one
    /// once it is over; 0 in pool.
    int frame_score(int player) const { return frame_score_[player == 2 ? 1 : 0]; }

private:
    void end_rack(int winner);

    GameType game_;
    StatsKind kind_;
    std::array<PlayerStats, 2> stats_;
    std::array<int, 2> frame_score_{};
    int visitor_ = 0;             // the player at the table in the current visit, 0 between visits
    int run_ = 0;                 // balls potted (snooker: points scored) in the current visit
    bool run_from_break_ = false; // the current visit began with its player's break
    bool rack_over_ = false;      // the last rack or frame has a winner: the next shot starts one
};

/// Replays `record` and tallies its shots: the figures of a saved or finished game. An action
/// the game refuses is an error at its line, as for Match::replay.
std::variant<StatsTally, RecordError> tally_record(const GameRecord& record);

/// Both players' figures for a recorded game (player 1 first), or the replay's error.
std::variant<std::array<PlayerStats, 2>, RecordError> stats_of_record(const GameRecord& record);

} // namespace termpool
