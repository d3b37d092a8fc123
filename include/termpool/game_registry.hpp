#pragma once
/// \file
/// The game types, one row each: a game's names, its table and rack, its referee, its default
/// break, its words, its panel's lines and the statistics it keeps. Everything outside the
/// core that differs between games reads it here rather than naming a game type; adding a
/// game is its referee's file and one row (game_registry.cpp).

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <termpool/ball.hpp>
#include <termpool/rack.hpp>
#include <termpool/rules.hpp>
#include <termpool/table.hpp>
#include <vector>

namespace termpool {

class Referee;

/// The balls a game is played with.
enum class BallSet {
    pool,    ///< the cue ball and the object balls 1-15, numbered
    snooker, ///< the cue ball, 15 reds (1-15) and the six colours (16-21)
};

/// The highest ball of `set`: 15 or 21.
int last_ball(BallSet set);

/// Where the default break is aimed.
enum class BreakAim {
    head_ball, ///< full at the object ball nearest the head of the table (the apex ball)
    end_red,   ///< thin off the back red of the pack on the cue ball's side (snooker's break-off)
};

/// What a shot after the break calls.
enum class CallRule {
    nothing,       ///< nothing is called (9-ball)
    every_pot,     ///< a pot counts only with its ball and pocket called (8-ball, 10-ball)
    deciding_ball, ///< only the deciding ball's pocket is called (bar rules' 8)
    ball_on,       ///< the ball on is named, its pocket left out or not (snooker's nomination)
};

/// The break a player starts from: its speed and its aim.
struct DefaultBreak {
    double speed = 12.0;                ///< the cue ball's speed, m/s
    BreakAim aim = BreakAim::head_ball; ///< where it is aimed (`break_aim_deg`)
};

/// How a game is won, and a match of them counted.
enum class Scoring {
    racks,  ///< the game is won by its deciding shot; a match is a race to N racks
    points, ///< the frame is won on points; a match is the best of N frames
};

/// The words a game is spoken of in.
struct GameWords {
    const char* unit = "rack";                      ///< one game of a match: "rack", "frame"
    const char* units = "racks";                    ///< its plural
    const char* rematch = "rematch (loser breaks)"; ///< the offer to play another at the end
    const char* new_game = "new game";              ///< the offer to start afresh at the end
    /// The offer to play another match at the end of one.
    const char* match_rematch = "rematch (loser breaks)";
    const char* breaks = "breaks";    ///< what the breaker does: "breaks", "breaks off"
    const char* break_shot = "break"; ///< the shot: "break", "break-off"
    const char* heading = "Rack";     ///< the unit starting a line: "Rack 2", "Frame 2"
};

/// What the panel shows under each player's name.
enum class PlayerLine {
    group,          ///< the player's group and what of it has dropped, or "open table"
    fouls_in_a_row, ///< the player's fouls in a row, the second one as a warning
    highest_break,  ///< the player's highest break of the frame
};

/// The pocketed balls the panel lists.
enum class PocketedLine {
    none,           ///< none (snooker's colours come back, its reds are counted elsewhere)
    outside_groups, ///< those of nobody's group (all of them on an open table)
    all,            ///< every ball that has dropped
};

/// The panel's lines of a game.
struct PanelLines {
    PlayerLine player = PlayerLine::group;                ///< under each name
    PocketedLine pocketed = PocketedLine::outside_groups; ///< the balls down
};

/// Which figures a game type keeps for its players (stats.hpp tallies them, the player's files
/// and the game-over box show them).
enum class StatsKind {
    pool,    ///< racks won, balls potted, break-and-runs and the longest run
    snooker, ///< frames won, points, frame scores, the highest break and centuries
};

/// One game type: all that differs between games, outside its referee.
struct GameRow {
    GameType type = GameType::eight_ball;   ///< the type
    const char* name = "";                  ///< as written in records and options: "8ball"
    std::vector<std::string> other_names{}; ///< other spellings read as it: "ten-ball"
    const char* title = "";                 ///< as shown to players: "8-ball, bar rules"
    /// The table the game is always played on (snooker's), or none: the player's choice.
    std::optional<TableSize> table{};
    RackType rack = RackType::eight_ball;        ///< how a rack is set up
    BallSet balls = BallSet::pool;               ///< what the balls are, drawn and named
    int deciding_ball = 0;                       ///< the ball that wins (8, 9, 10), 0: none
    BallInHand break_from = BallInHand::kitchen; ///< where the breaker places the cue ball
    DefaultBreak default_break;                  ///< the break a player starts from
    CallRule calls = CallRule::every_pot;        ///< what a shot calls (the referee judges it)
    bool groups = false;                         ///< the players take groups (solids and stripes)
    bool push_out = false;             ///< a push-out may be declared on the shot after the break
    GameWords words;                   ///< its words
    Scoring scoring = Scoring::racks;  ///< racks or points
    PanelLines panel;                  ///< the panel's lines
    StatsKind stats = StatsKind::pool; ///< the statistics it keeps
    /// Makes the referee of a new game of this type.
    std::unique_ptr<Referee> (*make_referee)() = nullptr;
};

/// The game types known: the standard ones, and any a test adds.
class GameRegistry {
public:
    /// The standard games, in this order: 8-ball (WPA, bar rules), 9-ball, 10-ball, snooker.
    static GameRegistry standard();

    /// Adds `row` at the end. False (nothing added) when its type or one of its names is
    /// taken, or it has no referee.
    bool add(GameRow row);

    /// The rows, in order.
    const std::vector<GameRow>& rows() const { return rows_; }
    /// The row of `type`, null when there is none.
    const GameRow* find(GameType type) const;
    /// The row named `name` (its name or another spelling), null when there is none.
    const GameRow* find(std::string_view name) const;
    /// The row after `type`'s, the first after the last: a picker cycling through the games.
    const GameRow& next(GameType type) const;

private:
    std::vector<GameRow> rows_;
};

/// The game a setup, a view or a request has until one is chosen: the first standard row's.
inline constexpr GameType default_game = GameType::eight_ball;

/// The standard games (`GameRegistry::standard`), made once.
const GameRegistry& game_registry();

/// The row of `type` among the standard games; the first row (8-ball) for a type that has none
/// (a game only a test's own registry knows, shown with 8-ball's words rather than failing).
const GameRow& game_row(GameType type);

/// True when `call` names a ball of `row`'s set into a pocket 1-6, the pocket left out (0)
/// where the ball on is called: what a record and a match accept as a call.
bool call_fits(const GameRow& row, const Call& call);

/// The angle of `row`'s default break, degrees counter-clockwise from +x, from the cue ball of
/// `balls` (a rack with the cue ball placed) with balls of radius `ball_radius`: full at the
/// head ball, or the line `break_clip` radii outside the end red. 0 when there is nothing to aim
/// at.
double break_aim_deg(const GameRow& row, const std::vector<Ball>& balls, double ball_radius);

/// How far outside the end red's centre snooker's break-off passes, in ball radii: a thin
/// contact on its outer side.
inline constexpr double break_clip = 1.6;

} // namespace termpool
