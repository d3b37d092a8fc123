#pragma once
/// \file
/// A game, or a race-to-N match of games, as a record: the rules context, the seed and the list
/// of what the players did. The simulator is deterministic, so replaying the record rebuilds
/// the game exactly. The text form is what the game saves (see the man page, FILES).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <termpool/assist.hpp>
#include <termpool/level.hpp>
#include <termpool/race.hpp>
#include <termpool/rules.hpp>
#include <termpool/setup.hpp>
#include <variant>
#include <vector>

namespace termpool {

/// Newest version of the text form, read and written by this build. Version 2 added races,
/// version 3 the cue (a `cue` line for a shaft other than the standard one, a shot's
/// `elevation`), version 4 the check (a `physics` line and a `check` line), version 5 the
/// assist (an `assist` line for an assist other than standard), version 6 the running check
/// (over every action, not only the last state) and one text for every line: each action
/// line exactly as `format_action` writes it, each number as `format_double` or
/// `std::to_string` writes it. A record is written in the oldest version that holds it, so
/// that older builds read it; a record with a check is version 6.
inline constexpr int record_version = 6;

/// One thing a player did, or the start of a match's next rack.
struct RecordedAction {
    /// A placement of the cue ball, a choice, a shot, or a new rack.
    enum class Kind { place, choose, shot, rack };
    Kind kind = Kind::shot;          ///< which
    Vec2 place;                      ///< place: where the cue ball went
    Choice choice = Choice::play_on; ///< choose: the option taken
    Strike strike;                   ///< shot: the strike
    ShotCall call;                   ///< shot: the call
    int breaker = 1;                 ///< rack: who breaks it (as the break rule says)
    std::uint64_t seed = 1;          ///< rack: its rack seed
    int line = 0;                    ///< the line it was read from (0 when made in memory)
};

/// What a record's writer saw, so that a reader can tell whether its replay gives the same
/// game (`Match::replay` compares).
struct RecordCheck {
    int physics_version = 0; ///< the writer's `physics_version` (simulator.hpp)
    /// The writer's `Match::check_hash` after the last action (`final_check_hash` when not
    /// `running`).
    std::uint64_t hash = 0;
    int line = 0; ///< the `check` line it was read from (0 when made in memory)
    /// True for the check of version 6 on, a digest over every action and the state after it;
    /// false for versions 4 and 5, whose check names only the state after the last action.
    bool running = true;
};

/// A whole game, or a whole match: its racks after the first each start with a rack action.
struct GameRecord {
    /// The rules, the table and the physics; a record keeps the cloth model and the cue ball's
    /// mass, the other constants are the defaults (the balls' size and mass follow the table:
    /// game_physics).
    GameSetup setup;
    std::uint64_t seed = 1;                          ///< the first rack's seed
    int breaker = 1;                                 ///< who broke the first rack
    std::string names[2] = {"Player 1", "Player 2"}; ///< the players
    std::optional<Level> computers[2];               ///< a computer in a seat, and its level
    int race_to = 1;                                 ///< racks to win the match; 0 or 1: one game
    BreakRule break_rule = BreakRule::alternate;     ///< who breaks each next rack
    /// How much the aiming aid helps both seats (no line: standard, as in older records).
    Assist assist = Assist::standard;
    std::vector<RecordedAction> actions; ///< in order
    /// The state the actions led to when the record was written: a Match keeps it after every
    /// action; records of version 3 and older have none.
    std::optional<RecordCheck> check;
};

/// True for a name a seat may take: 1 to `max_player_name_bytes` bytes of UTF-8 without control
/// characters (C0, DEL, C1) and without a space at either end (the record keeps it on one line).
bool valid_player_name(std::string_view name);

/// Longest name a seat may take, in bytes (a front end may allow fewer columns).
inline constexpr std::size_t max_player_name_bytes = 80;

/// Why a record was refused.
struct RecordError {
    int line = 0;        ///< 1-based line
    std::string message; ///< what is wrong
};

/// The text form of a record. Numbers are written so that they read back bit for bit.
std::string format_record(const GameRecord& record);

/// The text of one action as a record writes it, without the newline ("place 0.6 0.5",
/// "shot 12 0 0 0 call 1 3", "choose play-on", "rack 2 1234"): what the hall sends.
std::string format_action(const RecordedAction& action);

/// Reads one action line as `format_action` writes it; an error says what is wrong (line 1).
std::variant<RecordedAction, RecordError> parse_action(std::string_view line);

/// Reads the text form; an error names the line and the problem (truncated, foreign, from a
/// newer version, bad values).
std::variant<GameRecord, RecordError> parse_record(std::string_view text);

/// The seed for rack `rack` (from 1) of a match: the record's seed for the first, a mix of it
/// and the number for the others. Rack actions store the seed, so this may change freely.
std::uint64_t rack_seed(std::uint64_t record_seed, int rack);

/// The action that starts rack `rack` (2, 3, ...) of `record`'s match with `breaker` to break,
/// seeded with `rack_seed`.
RecordedAction rack_action(const GameRecord& record, int rack, int breaker);

} // namespace termpool
