#pragma once
/// \file
/// The flow of a game or a race-to-N match, for every front end: the setup, the two seats, the
/// current rack's Game, the score, the record and the players' figures. It says who must act
/// and what they may do, takes their actions (each validated, each recorded), plays the shots,
/// asks a seated computer for its move, and replays a record up to any action. No terminal, no
/// I/O: the local game, `termpool selfplay` and the hall all drive this same code.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <termpool/computer.hpp>
#include <termpool/race.hpp>
#include <termpool/record.hpp>
#include <termpool/rules.hpp>
#include <termpool/setup.hpp>
#include <termpool/simulator.hpp>
#include <termpool/stats.hpp>
#include <variant>
#include <vector>

namespace termpool {

/// Who sits in a seat.
struct Seat {
    std::string name;              ///< as shown and saved
    std::optional<Level> computer; ///< the computer plays this seat, at this level
};

/// What a match waits for.
enum class Pending {
    place,     ///< the player to act has the cue ball in hand: `place` it (or shoot it from
               ///< where it lies, if that is a legal spot)
    shoot,     ///< the player to act shoots
    choose,    ///< the player to act owes a choice
    next_rack, ///< a race goes on: the rack is won and `next_rack` racks the next one
    over,      ///< the game, or the match, is won
};

/// What the match waits for, and the options the rules give.
struct PendingAction {
    Pending kind = Pending::shoot; ///< which
    /// Who must act (1 or 2): the chooser, the shooter, or who breaks the next rack; 0 when over.
    int player = 0;
    /// Where the cue ball may go while the shooter has it in hand (none without ball in hand).
    BallInHand ball_in_hand = BallInHand::none;
    std::vector<Choice> choices; ///< choose: the options, in the order the rules list them
};

/// Why an action was refused; nothing changed.
enum class MatchError {
    none,         ///< taken
    over,         ///< the game or the match is over
    wrong_player, ///< it is the other seat's turn (or no such seat)
    not_now,      ///< the match waits for another kind of action
    illegal_spot, ///< the cue ball may not go there
    bad_strike,   ///< a strike the simulator refuses (strike_problem says why)
    bad_call,     ///< a call of a ball or pocket that does not exist
    not_offered,  ///< the choice is not among those on offer
    bad_name,     ///< blank, too long, spaces at an end, or control characters
    bad_race,     ///< a race outside 1 to max_race_to racks
    started,      ///< the race can only be set before the first action
    bad_setup,    ///< a breaker other than 1 or 2, or physics a record cannot keep
};

/// A few words for `error` ("it is the other player's turn", ...).
const char* match_error_text(MatchError error);

/// A shot as the match played it.
struct PlayedShot {
    int shooter = 1;        ///< who played it
    int rack = 1;           ///< the rack it was played in, from 1
    bool was_break = false; ///< it was a break
    ShotCall call;          ///< the call as the referee took it (push_out only where allowed)
    Verdict verdict;        ///< what it meant
    ShotResult result;      ///< the simulation: events, final balls, time to rest
};

/// Hears each shot of a replay.
using ShotListener = std::function<void(const PlayedShot& shot)>;

/// What a seated computer decided to do.
struct ComputerMove {
    Pending kind = Pending::shoot;   ///< place, shoot or choose
    Vec2 spot;                       ///< place: where the cue ball goes
    ComputerShot shot;               ///< shoot: the strike and the call
    Choice choice = Choice::play_on; ///< choose: the option taken
};

/// True when `strike`'s numbers are in the simulator's ranges: finite, speed 0 to
/// max_strike_speed, tip offsets within half a radius, elevation 0 to max_cue_elevation_deg.
/// The jump-shot limit depends on the physics as well: `strike_problem` checks both.
bool strike_in_range(const Strike& strike);

/// One game, or a race of games, between seats 1 and 2.
class Match {
public:
    /// A new match set up as `header` says (its setup, seed, breaker, seats, race and break
    /// rule; its actions are not played, see `replay`), or why not: a breaker other than 1 or
    /// 2 (wrong_player), a bad name, a race outside 0 to max_race_to, or physics the record
    /// cannot keep (bad_setup: a record keeps the cloth model, the cue ball's mass and the cue, the
    /// other constants must be the defaults). A computer seat's decisions come from `computer_seed`
    /// + the seat's number.
    static std::variant<Match, MatchError> start(const GameRecord& header,
                                                 std::uint64_t computer_seed = 0);

    /// The next game between the same seats, with the same setup and race: `breaker` breaks a
    /// rack racked from `seed`. The computers play on with their own streams, as a person would
    /// remember the last game.
    Match rematch(int breaker, std::uint64_t seed) &&;

    /// Plays the first `actions` actions of `record` (all of them by default) on a new match;
    /// `on_shot` hears each shot. An action the match refuses (a record edited into an impossible
    /// state) is an error at its line; so is a rack action before the rack is won, after the
    /// match is, or with a breaker other than the break rule's. A whole replay of a record with
    /// a check must end in the state the check names: a record from another physics version
    /// that still does is replayed, one that does not is refused (an error that names both
    /// physics versions), and so is one of this version whose replay differs (edited).
    static std::variant<Match, RecordError>
    replay(const GameRecord& record, std::size_t actions = std::numeric_limits<std::size_t>::max(),
           const ShotListener& on_shot = {}, std::uint64_t computer_seed = 0);

    /// The game, the table and the physics.
    const GameSetup& setup() const { return record_.setup; }
    /// The table played on.
    const Table& table() const { return game_.table(); }
    /// The current rack.
    const Game& game() const { return game_; }
    /// Everything done so far, as a save holds it.
    const GameRecord& record() const { return record_; }
    /// The race and the racks won; a rack counts once it is won.
    const MatchState& score() const { return score_; }
    /// The current rack's number, from 1.
    int rack() const { return rack_; }
    /// Who was given the current rack's break (re-racks aside).
    int rack_breaker() const { return rack_breaker_; }
    /// The seat of `player` (1 or 2).
    Seat seat(int player) const;
    /// The name of `player` (1 or 2).
    const std::string& name(int player) const { return record_.names[player == 2 ? 1 : 0]; }
    /// The players' figures so far.
    const StatsTally& tally() const { return tally_; }
    /// A 64-bit digest (FNV-1a) of everything a replay must agree on: the balls to the bit, the
    /// turn, ball in hand, choices, groups, fouls, the score, the rack and the number of
    /// actions. Two copies that played the same actions have the same hash on any build that
    /// computes the same doubles.
    std::uint64_t state_hash() const;
    /// What a record's `check` line holds (version 6 on): a running digest over every action,
    /// its text as the record writes it and the `state_hash` after it, then the race (its
    /// length and break rule, which the header gives and no action repeats). An edited action
    /// moves it even when later actions bring the balls back to where they were.
    std::uint64_t check_hash() const;
    /// What the `check` line of a record of version 4 or 5 holds: `state_hash` after the last
    /// action and the race; such records are still read, and compared with this.
    std::uint64_t final_check_hash() const;

    /// What the match waits for and from whom.
    PendingAction pending() const;
    /// The player who must act (1 or 2), 0 once the match is over.
    int to_act() const { return pending().player; }
    /// True once an action has been taken and until the match is over: a game a player who
    /// leaves would come back to (the hall keeps such a player's seat).
    bool under_way() const { return !record_.actions.empty() && pending().kind != Pending::over; }
    /// True when the player to act is a computer.
    bool computer_to_act() const;
    /// Who breaks the next rack, once the current one is won: 1 or 2 (0 before).
    int next_breaker() const;
    /// True when a shot at `ball` must name its pocket: 8-ball and 10-ball after the break, the
    /// 8 only in bar rules, never in 9-ball.
    bool calls_pocket(int ball) const;

    /// Puts the cue ball at `spot` for `player`'s ball in hand.
    MatchError place(int player, Vec2 spot);
    /// `player` shoots: the shot is simulated (into `trajectory` when given, for animation),
    /// judged and recorded.
    std::variant<PlayedShot, MatchError>
    shoot(int player, const Strike& strike, const ShotCall& call, Trajectory* trajectory = nullptr);
    /// `player` makes the choice owed; Choice::concede, never owed, is `concede(player)`.
    MatchError choose(int player, Choice choice);
    /// Snooker: `player`, who is to act, concedes the frame; recorded as `choose concede`.
    /// not_offered in another game.
    MatchError concede(int player);
    /// Racks the next rack of a race once the current one is won (either player may).
    MatchError next_rack(int player);
    /// Gives `player`'s seat a new name.
    MatchError rename(int player, std::string_view name);
    /// Seats a computer of `level` (or, with none, a person) in `player`'s seat.
    MatchError seat_computer(int player, std::optional<Level> level);
    /// Sets the race before the first action: `race_to` racks (1 is a single game).
    MatchError set_race(int race_to);

    /// Applies one recorded action for whoever is to act, as a replay does; a shot is simulated
    /// into `trajectory` when given, and `shot` (when given) receives it.
    MatchError apply(const RecordedAction& action, Trajectory* trajectory = nullptr,
                     PlayedShot* shot = nullptr);

    /// The move of the computer seated at the player to act (nothing when a person acts, or
    /// the match is over or waits for the next rack). Ask once per decision: the computer's
    /// stream moves on with each question. A snooker computer that concedes (see
    /// `ComputerPlayer::concedes`) answers with kind choose and Choice::concede.
    std::optional<ComputerMove> computer_move();
    /// Seats the computers afresh, their decisions from `computer_seed` + the seat's number (a
    /// resumed game's computers start new streams).
    void reseed_computers(std::uint64_t computer_seed);
    /// Shots simulated so far by the computer in `player`'s seat (0 for a person).
    std::uint64_t computer_simulations(int player) const;

private:
    Match(const GameRecord& header, std::uint64_t computer_seed);
    MatchError check_player(int player) const;
    void start_rack(int breaker, std::uint64_t seed);
    void count_rack();
    /// `replay` without the comparison with the record's check.
    static std::variant<Match, RecordError> replay_unchecked(const GameRecord& record,
                                                             std::size_t actions,
                                                             const ShotListener& on_shot,
                                                             std::uint64_t computer_seed);
    /// Keeps the record's check up to date after an action was added to the record, or
    /// (`replaced_last`) after the last one was replaced (a cue ball placed again).
    void stamp_check(bool replaced_last = false);

    GameRecord record_;
    Game game_;
    MatchState score_;
    int rack_ = 1;
    int rack_breaker_ = 1;
    bool rack_counted_ = false;
    bool placed_ = false; // the cue ball in hand was placed this turn
    StatsTally tally_;
    std::uint64_t computer_seed_ = 0;
    std::optional<ComputerPlayer> computers_[2];
    // Where a digest of nothing starts (FNV-1a's offset basis, as StateDigest starts; match.cpp
    // checks that they agree).
    static constexpr std::uint64_t empty_digest = 0xcbf29ce484222325ULL;
    // The running digest of check_hash over the actions so far, and over all but the last (a
    // replaced last action is folded in again from there).
    std::uint64_t actions_digest_ = empty_digest;
    std::uint64_t actions_digest_before_last_ = empty_digest;
};

} // namespace termpool
