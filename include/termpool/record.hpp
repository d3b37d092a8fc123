#pragma once
/// \file
/// A game as a record: the rules context, the seed and the list of what the players did. The
/// simulator is deterministic, so replaying the record rebuilds the game exactly. The text
/// form is what the game saves (see the man page, FILES).

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <termpool/computer.hpp>
#include <termpool/rules.hpp>
#include <variant>
#include <vector>

namespace termpool {

/// Version of the text form written by this build.
inline constexpr int record_version = 1;

/// One thing a player did.
struct RecordedAction {
    enum class Kind { place, choose, shot };
    Kind kind = Kind::shot;          ///< which
    Vec2 place;                      ///< place: where the cue ball went
    Choice choice = Choice::play_on; ///< choose: the option taken
    Strike strike;                   ///< shot: the strike
    ShotCall call;                   ///< shot: the call
    int line = 0;                    ///< the line it was read from (0 when made in memory)
};

/// A whole game.
struct GameRecord {
    GameType game = GameType::eight_ball;            ///< the rules
    TableSize table = TableSize::nine_foot;          ///< the table
    std::uint64_t seed = 1;                          ///< the rack seed
    int breaker = 1;                                 ///< who broke the first rack
    std::string names[2] = {"Player 1", "Player 2"}; ///< the players
    std::optional<Level> computers[2];               ///< a computer in a seat, and its level
    FrictionModel friction;                          ///< the cloth model
    double cue_ball_mass = 0;                        ///< 0: like the other balls
    std::vector<RecordedAction> actions;             ///< in order
};

/// Why a record was refused.
struct RecordError {
    int line = 0;        ///< 1-based line
    std::string message; ///< what is wrong
};

/// The text form of a record. Numbers are written so that they read back bit for bit.
std::string format_record(const GameRecord& record);

/// Reads the text form; an error names the line and the problem (truncated, foreign, from a
/// newer version, bad values).
std::variant<GameRecord, RecordError> parse_record(std::string_view text);

/// The physics a record is played with.
PhysicsParams record_params(const GameRecord& record);

/// Plays the record's actions on a new game. An action the game refuses (a record edited into
/// an impossible state) is an error at its line.
/// `on_shot`, when given, hears each shot's shooter and verdict.
std::variant<Game, RecordError>
replay_record(const GameRecord& record,
              const std::function<void(int shooter, const Verdict& verdict)>& on_shot = {});

/// One shot of a replay, for listeners that need more than who shot and the verdict.
struct ReplayedShot {
    int shooter = 1;        ///< who played it
    bool was_break = false; ///< it was a break
    ShotCall call;          ///< the call as the game took it (push_out only when allowed)
    Verdict verdict;        ///< what it meant
};

/// replay_record, with `on_shot` hearing each shot in full.
std::variant<Game, RecordError>
replay_record_shots(const GameRecord& record,
                    const std::function<void(const ReplayedShot& shot)>& on_shot);

} // namespace termpool
