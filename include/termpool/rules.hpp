#pragma once
/// \file
/// The referee: 8-ball (WPA rules and bar rules), 9-ball and 10-ball (WPA rules) and snooker
/// (WPBSA rules, as far as the simulator can judge them) on top of the simulator. A Game holds
/// the balls on the table and whose turn it is, and its game type's referee (referee.hpp, made
/// by the type's row in game_registry.hpp); `apply` reads the events of a shot and the referee
/// decides what they mean. Choices the rules owe a player are explicit inputs (`choose`), never
/// guessed.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <termpool/ball.hpp>
#include <termpool/params.hpp>
#include <termpool/rack.hpp>
#include <termpool/simulator.hpp>
#include <termpool/table.hpp>
#include <vector>

namespace termpool {

/// Which game is played.
enum class GameType {
    eight_ball,     ///< WPA 8-ball: called shots, ball in hand anywhere after a foul
    eight_ball_bar, ///< bar rules: only the 8 is called, ball in hand in the kitchen
    nine_ball,      ///< WPA 9-ball: lowest ball first, push-out after the break
    ten_ball,       ///< WPA 10-ball: lowest ball first, every shot called, push-out after the break
    snooker,        ///< snooker (WPBSA): reds and colours, points, fouls give points away
};

/// An 8-ball group.
enum class Group {
    open,    ///< not assigned yet
    solids,  ///< balls 1-7
    stripes, ///< balls 9-15
};

/// Where the incoming player may place the cue ball.
enum class BallInHand {
    none,     ///< the cue ball stays where it is
    kitchen,  ///< behind the head string (x <= L/4)
    anywhere, ///< anywhere on the table
    d,        ///< snooker: inside the D (in_snooker_d)
};

/// Fouls, in order of precedence: when several happen on one shot, the verdict names the
/// first in this order (all of them are listed as well).
enum class Foul {
    none,              ///< a legal shot
    scratch,           ///< the cue ball was pocketed
    cue_off_table,     ///< the cue ball left the table
    off_table,         ///< an object ball left the table
    no_contact,        ///< the cue ball hit no ball
    wrong_ball_first,  ///< the first ball hit was not a legal target
    no_rail,           ///< after the first contact, nothing was pocketed and no ball hit a cushion
    bad_break,         ///< 9-ball, 10-ball: the break pocketed nothing and drove fewer than four
                       ///< balls to a cushion (in 8-ball an illegal break is not a foul but owes
                       ///< a choice)
    pot_not_on,        ///< snooker: a ball that was not on was potted
    free_ball_snooker, ///< snooker: the free ball, not potted, left the opponent snookered
};

/// Decisions the rules owe a player.
enum class Choice {
    play_on,            ///< accept the table as it is and shoot
    re_rack,            ///< re-rack and break yourself
    re_break,           ///< the player who just broke breaks again
    spot_eight,         ///< 8 pocketed on the break: spot it and keep shooting
    take_solids,        ///< bar rules, both groups fell on the break: take solids
    take_stripes,       ///< bar rules: take stripes
    shoot,              ///< after a push-out (or a 10-ball ball pocketed uncalled): shoot from here
    pass_back,          ///< after a push-out (or a 10-ball ball pocketed uncalled): the player who
                        ///< played the shot shoots again
    offender_plays,     ///< snooker, after a foul: the player who fouled plays again from there
    replace_and_replay, ///< snooker, after a miss: the balls go back and the offender plays again
    concede,            ///< snooker: the player to act concedes the frame (`Game::concede`)
};

/// Why the game ended.
enum class WinReason {
    none,               ///< not over
    eight_pocketed,     ///< the called 8 was pocketed legally
    eight_on_break,     ///< bar rules: the 8 fell on the break
    eight_early,        ///< the opponent pocketed the 8 before clearing the group
    eight_on_foul,      ///< the opponent pocketed the 8 on a foul (or scratched with it, bar rules)
    eight_wrong_pocket, ///< the opponent pocketed the 8 in a pocket not called
    eight_off_table,    ///< the opponent drove the 8 off the table
    nine_pocketed,      ///< the 9 was pocketed legally
    three_fouls,        ///< the opponent fouled three times in a row (9-ball, 10-ball)
    ten_pocketed,       ///< the called 10 was pocketed legally in the called pocket
    frame_won,          ///< snooker: the frame ended with more points than the opponent
    conceded,           ///< snooker: the opponent conceded the frame
    three_misses,       ///< snooker: the opponent missed three times running, the balls replaced
};

/// Snooker: what the shooter must hit first.
enum class BallOn {
    red,      ///< any red
    colour,   ///< a colour, after a red: the nominated one (Call.ball 16..21)
    in_order, ///< the reds are gone: the lowest colour on the table
};

/// Snooker: the referee's score sheet of a frame.
struct SnookerState {
    int scores[2] = {0, 0};        ///< points of players 1 and 2
    int current_break = 0;         ///< points of the shooter's visit so far
    int highest_break[2] = {0, 0}; ///< each player's highest break of the frame
    BallOn ball_on = BallOn::red;  ///< what the shooter is on
    bool free_ball = false;        ///< the shooter may nominate any ball as the ball on
    bool respotted_black = false;  ///< the scores were level at the end: re-spotted black
    int misses[2] = {0, 0};        ///< misses in a row of each player, the balls replaced
    bool operator==(const SnookerState&) const = default; ///< exact equality
};

/// A called shot. Ball 0 means "not called": the referee calls the obvious shot for the
/// shooter, namely the first ball contacted into whichever pocket it drops in. In snooker the
/// ball is the nomination (a colour after a red, or the free ball) and the pocket may be 0.
struct Call {
    int ball = 0;        ///< the ball called, 0 for none
    int pocket = 0;      ///< its pocket 1..6
    bool safety = false; ///< the shooter called safety: the turn passes whatever drops
    bool operator==(const Call&) const = default; ///< the same ball, pocket and safety
};

/// What the shooter declared for a shot besides the strike.
struct ShotCall {
    Call call;                                        ///< 8-ball and 10-ball calls
    bool push_out = false;                            ///< 9-ball, 10-ball: this shot is a push-out
    bool operator==(const ShotCall&) const = default; ///< the same call and push-out
};

/// What a shot meant.
struct Verdict {
    Foul foul = Foul::none;                     ///< the foul that counts, or none
    std::vector<Foul> fouls;                    ///< every foul of the shot, in precedence order
    int first_contact = -1;                     ///< first ball the cue ball hit, -1 for none
    std::vector<int> pocketed;                  ///< balls that dropped, in order
    bool legal_break = true;                    ///< for a break shot: did it meet the break rule
    bool groups_assigned = false;               ///< groups were decided by this shot
    Group player1_group = Group::open;          ///< groups after the shot (player 2 has the other)
    int next_shooter = 1;                       ///< 1 or 2
    BallInHand ball_in_hand = BallInHand::none; ///< for the next shooter
    int chooser = 0;                            ///< player who owes a choice (0: none)
    std::vector<Choice> choices;                ///< the options of that choice
    std::vector<int> respotted;                 ///< balls put back on the table (the 8, 9, 10)
    int winner = 0;                             ///< 1 or 2 once the game is over
    WinReason reason = WinReason::none;         ///< why
    bool stalemate_rerack = false;              ///< the rack was re-broken for a stalemate
    int points = 0;                             ///< snooker: points the shooter scored
    int penalty = 0;                            ///< snooker: foul points given to the opponent
    int nominated = 0;                          ///< snooker: the colour or free ball taken as on
    bool miss = false;                          ///< snooker: the foul is also a miss
    bool free_ball = false;                     ///< snooker: the next player may take a free ball
};

/// The rack `type` is played from (its row's, see game_registry.hpp).
RackType game_rack(GameType type);

/// The name of `type` as written in records and options ("8ball", "9ball", ...: its row's).
const char* game_type_name(GameType type);
/// Parses a game name ("8ball", "8ball-bar", "9ball", "10ball", "snooker"; 10-ball also as
/// "ten-ball" or "10-ball"); nothing for an unknown one.
std::optional<GameType> parse_game_type(const std::string& name);
/// "solids", "stripes" or "open".
const char* group_name(Group group);
/// "none", "kitchen", "anywhere" or "d".
const char* ball_in_hand_name(BallInHand bih);
/// "none", "scratch", ...
const char* foul_name(Foul foul);
/// "play-on", "re-rack", ...
const char* choice_name(Choice choice);
/// "eight-pocketed", ...
const char* win_reason_name(WinReason reason);

/// "red", "colour" or "in-order".
const char* ball_on_name(BallOn on);

/// The balls of a group (1-7 or 9-15); empty for `open`.
std::vector<int> group_balls(Group group);
/// Whether ball `id` is one of group_balls(group), without making the list.
constexpr bool in_group(Group group, int id) {
    return (group == Group::solids && id >= 1 && id <= 7) ||
           (group == Group::stripes && id >= 9 && id <= 15);
}

/// Snooker: true when the cue ball at `cue` cannot hit both extreme edges of any ball of
/// `on` in a straight line, each edge's line being blocked by a ball not in `on` (the WPBSA
/// definition; cushions and pocket jaws are not considered). False when `on` is empty.
bool snookered(const std::vector<Ball>& balls, Vec2 cue, const std::vector<int>& on, double R);

/// What every game shares, whatever its rules: the table, the balls and whose turn it is. The
/// Game owns it; its referee (referee.hpp) reads it and moves it on.
struct GameState {
    Table table;                                   ///< the table played on
    PhysicsParams params;                          ///< the physics the shots are simulated with
    std::vector<Ball> balls;                       ///< pocketed ones are kept, state pocketed
    RackType rack = RackType::eight_ball;          ///< what a new rack is racked as
    BallInHand break_from = BallInHand::kitchen;   ///< where the breaker places the cue ball
    std::uint64_t seed = 1;                        ///< the game's seed; each rack has its own
    int racks = 0;                                 ///< racks racked so far
    int shooter = 1;                               ///< the player to shoot (or choose): 1 or 2
    int breaker = 1;                               ///< the player who broke this rack
    bool is_break = true;                          ///< the next shot is a break
    BallInHand ball_in_hand = BallInHand::kitchen; ///< where the shooter may place the cue ball
    int chooser = 0;                               ///< the player who owes a choice, 0 for none
    std::vector<Choice> choices;                   ///< the options of that choice
    int winner = 0;                                ///< 1 or 2 once the game is over
    WinReason reason = WinReason::none;            ///< why it ended

    /// The other player.
    static int opponent(int player) { return 3 - player; }
    /// True when ball `id` is on the table.
    bool on_table(int id) const;
    /// `player` wins the game, for `why`.
    void win(int player, WinReason why) {
        winner = player;
        reason = why;
    }
    /// Racks the balls anew (from the game's seed and the racks so far) with `new_breaker` to
    /// break with ball in hand. The referee's own state is its to forget (Referee::rerack).
    void rerack(int new_breaker);
    /// Puts ball `id` back on the foot spot, or the nearest free point behind it on the long
    /// string, or else in front of it (a pool ball spotted after it dropped).
    void spot_on_foot_string(int id);
    /// Exact equality of every field (the balls to the bit).
    bool operator==(const GameState&) const = default;
};

/// What a referee has written down besides the balls: the panel shows it, a game set up in the
/// middle (`Game::from_position`) starts from it, and the match's hash reads it. Each game keeps
/// the parts it uses; the others stay as they are here.
struct ScoreSheet {
    Group player1_group = Group::open; ///< 8-ball: player 1's group (player 2 has the other)
    bool push_out_allowed = false;     ///< 9-ball, 10-ball: a push-out may be declared now
    int fouls_in_a_row[2] = {0, 0};    ///< 9-ball, 10-ball: each player's fouls in a row
    SnookerState frame;                ///< snooker: the frame's points, breaks and ball on
    bool operator==(const ScoreSheet&) const = default; ///< exact equality
};

struct GameRow;
class Referee;

/// One game between players 1 and 2: the balls on the table, whose turn it is, and the referee
/// of its game type (game_registry.hpp) who judges the shots. A Game is a value: a copy has its
/// own copy of the referee and its state.
class Game {
public:
    /// A new game of `type`: the balls racked (seeded), `breaker` to break with ball in hand
    /// where the game breaks from.
    Game(GameType type, const Table& table, const PhysicsParams& params, int breaker = 1,
         std::uint64_t seed = 1);
    /// A new game of the type of `row`, which need not be one of the standard games (a test's
    /// own game, say).
    Game(const GameRow& row, const Table& table, const PhysicsParams& params, int breaker = 1,
         std::uint64_t seed = 1);

    /// A game in progress, for analysis: the balls as given, `shooter` to play, `player1_group`
    /// as the groups, `is_break` when the next shot is a break, `push_out_allowed` when it is
    /// the shot right after a 9-ball or 10-ball break. Ball in hand none. A snooker frame is on
    /// a red while any is on the table, else on the colours in order.
    static Game from_position(GameType type, const Table& table, const PhysicsParams& params,
                              std::vector<Ball> balls, int shooter, Group player1_group,
                              bool is_break, bool push_out_allowed = false);

    /// A snooker frame in progress, for analysis: the balls as given, `shooter` to play, the
    /// score sheet `state`, and where the cue ball may be placed (none or d).
    static Game from_snooker_position(const Table& table, const PhysicsParams& params,
                                      std::vector<Ball> balls, int shooter,
                                      const SnookerState& state,
                                      BallInHand ball_in_hand = BallInHand::none);

    /// A copy has a copy of the referee (`Referee::clone`): the two play on apart.
    Game(const Game& other);
    /// As the copy.
    Game& operator=(const Game& other);
    /// A moved-from game has no referee: it may only be assigned to or destroyed.
    Game(Game&& other) noexcept;
    /// As the move: `other` is left without a referee.
    Game& operator=(Game&& other) noexcept;
    ~Game();

    /// The game played.
    GameType type() const { return type_; }
    /// The balls, the turn and the choices: what every game shares.
    const GameState& state() const { return state_; }
    /// The referee of the game, for what only it knows.
    const Referee& referee() const { return *referee_; }
    /// The table played on.
    const Table& table() const { return state_.table; }
    /// The physics the shots are simulated with.
    const PhysicsParams& params() const { return state_.params; }
    /// The balls on the table (pocketed ones are kept with state pocketed).
    const std::vector<Ball>& balls() const { return state_.balls; }
    /// The player to shoot (or to choose, see `chooser`): 1 or 2.
    int shooter() const { return state_.shooter; }
    /// The player who broke this rack.
    int breaker() const { return state_.breaker; }
    /// True when the next shot is a break.
    bool is_break() const { return state_.is_break; }
    /// Where the shooter may place the cue ball before shooting.
    BallInHand ball_in_hand() const { return state_.ball_in_hand; }
    /// The player who owes a choice, 0 for none; `choices` lists the options.
    int chooser() const { return state_.chooser; }
    /// The options of the choice owed.
    const std::vector<Choice>& choices() const { return state_.choices; }
    /// 1 or 2 once the game is over, else 0.
    int winner() const { return state_.winner; }
    /// Why the game ended.
    WinReason win_reason() const { return state_.reason; }

    /// The referee's score sheet: groups, fouls in a row, a frame's points (see ScoreSheet).
    ScoreSheet score_sheet() const;
    /// Player 1's group; player 2 has the other one (open in a game without groups).
    Group player1_group() const { return score_sheet().player1_group; }
    /// The group of `player` (1 or 2).
    Group group_of(int player) const;
    /// True when a push-out may be declared on the next shot (9-ball, 10-ball).
    bool push_out_allowed() const { return score_sheet().push_out_allowed; }
    /// `call` as the referee takes it for the next shot: a push-out only where one is allowed.
    ShotCall call_as_taken(ShotCall call) const {
        call.push_out = call.push_out && push_out_allowed();
        return call;
    }
    /// Consecutive fouls of `player` (the 9-ball and 10-ball three-foul rule).
    int consecutive_fouls(int player) const {
        return score_sheet().fouls_in_a_row[player == 2 ? 1 : 0];
    }
    /// Balls the shooter may legally hit first now (9-ball, 10-ball: the lowest; 8-ball: the
    /// group, the 8 once the group is cleared; any but the 8 on an open table; snooker: the reds,
    /// any colour after a red, the lowest colour once the reds are gone, any ball with a free
    /// ball).
    std::vector<int> legal_targets() const;
    /// True when a shot at `ball` must name its pocket (never on a break).
    bool pocket_must_be_called(int ball) const;

    /// Snooker: the score sheet (zeros in other games).
    const SnookerState& snooker() const;
    /// Snooker: the points of `player` (1 or 2).
    int score_of(int player) const { return snooker().scores[player == 2 ? 1 : 0]; }
    /// The balls on for the shooter, before any nomination (snooker: the reds, every colour
    /// after a red, or the lowest colour; in other games the legal targets).
    std::vector<int> balls_on() const;
    /// Snooker: the ball on that the cue ball rests touching, -1 for none (the shooter must
    /// play away from it; moving it is not a foul).
    int touching_ball() const;
    /// Snooker: true when the shooter is snookered on every ball on (see `snookered`).
    bool shooter_snookered() const;
    /// Snooker: true when the shooter names the ball on with the shot's `Call.ball`: a colour
    /// after a red, or any ball with a free ball (without one the referee takes the ball hit
    /// first).
    bool nomination_owed() const;
    /// Snooker: true when the choice owed follows a foul that left the chooser snookered:
    /// playing on then gives a free ball.
    bool free_ball_offered() const;
    /// Snooker: the points still on the table for the player on now (reds at 8 each with a
    /// black, then the colours).
    int points_remaining() const;
    /// `player` concedes the frame (snooker); the opponent wins it. False (nothing changed) in
    /// a game that allows no concession, once the game is over, or for a player other than 1
    /// or 2.
    bool concede(int player);

    /// True when the cue ball may be placed at `p` now: inside the ball-in-hand area, on the
    /// playing surface, touching no ball.
    bool legal_placement(Vec2 p) const;
    /// A few legal cue-ball spots spread over the allowed area, for pickers and tests.
    std::vector<Vec2> legal_placements(int per_axis = 12) const;
    /// Places the cue ball for a ball in hand. Returns false (and changes nothing) when the
    /// spot is not legal or there is no ball in hand.
    bool place_cue_ball(Vec2 p);

    /// True when a shot may be played now: the game is on, no choice is owed, and the cue ball
    /// is on the table (where the ball in hand allows, if there is one).
    bool ready_to_shoot() const;

    /// Makes the choice owed. Returns false when `choice` is not one of `choices()`.
    bool choose(Choice choice);

    /// Judges a shot simulated from `balls()` and moves the game on: the balls take the
    /// result's final positions (with any re-spotting), and turn, groups, ball in hand, choices
    /// and the winner follow the rules. A shot while a choice is owed, a ball in hand is not
    /// placed, or after the end of the game is refused with a nothing-changed verdict where
    /// `next_shooter` is the current shooter.
    Verdict apply(const ShotCall& call, const ShotResult& result);

    /// What apply() works out before it looks at a result: a search that judges many results
    /// of one call from one game works it out once.
    struct ShotPlan {
        bool ready = false;       ///< ready_to_shoot()
        std::vector<int> targets; ///< the balls the call may hit first (when ready)
    };
    /// The plan of a shot with `call` from the game as it stands.
    ShotPlan plan(const ShotCall& call) const;
    /// apply() with `plan`, which plan(call) gave on this game as it stands now.
    Verdict apply(const ShotCall& call, const ShotResult& result, const ShotPlan& plan);

    /// Convenience: simulates `strike` from the current balls and applies it.
    Verdict play(const Strike& strike, const ShotCall& call, ShotResult* result = nullptr);

    /// Turns without progress (no object ball pocketed) after which a stalemate is declared,
    /// after which each player has three more turns before the rack is re-broken (pool).
    static constexpr int stalemate_warning_turns = 20;

private:
    Game() = default;
    static Game from_sheet(const GameRow& row, const Table& table, const PhysicsParams& params,
                           std::vector<Ball> balls, int shooter, bool is_break,
                           BallInHand ball_in_hand, const ScoreSheet& sheet);

    GameType type_ = GameType::eight_ball;
    GameState state_;
    std::unique_ptr<Referee> referee_;
};

} // namespace termpool
