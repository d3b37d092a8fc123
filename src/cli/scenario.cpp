#include "cli/scenario.hpp"

#include "support/text_lines.hpp"
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <termpool/game_registry.hpp>
#include <termpool/rack.hpp>
#include <termpool/rules_names.hpp>
#include <termpool/snooker_layout.hpp>
#include <termpool/table_physics.hpp>

#include "cli/numbers.hpp"

namespace termpool::cli {
namespace {

/// A line that holds a directive: its number and its fields, comment removed.
struct Line {
    int number = 0;
    std::vector<std::string_view> fields; ///< fields[0] is the directive's name
    /// Number of fields after the name.
    std::size_t arguments() const { return fields.size() - 1; }
    /// Field `i` after the name (0-based).
    std::string_view arg(std::size_t i) const { return fields[i + 1]; }
};

/// A problem with one line, before the line number is attached; empty when all is well.
using Problem = std::optional<std::string>;

/// The largest ball id of a pool table and of the snooker table (the black).
constexpr int pool_last_id = 15;
constexpr int snooker_last_id = snooker_black;

/// The ids a table takes, as a message says them.
std::string ball_id_range(bool snooker) {
    return snooker ? "0.." + std::to_string(snooker_last_id)
                   : "0.." + std::to_string(pool_last_id) + " (up to " +
                         std::to_string(snooker_last_id) + " on 'table snooker')";
}

/// A `ball` line, kept until the parameters are final (R and m may come later in the file).
struct BallLine {
    int line = 0;
    Ball ball;
    bool has_mass = false;
};

/// Everything the directives said, not yet checked against each other.
struct Draft {
    GameSetup setup; ///< the game, the table's size and the physics
    std::optional<int> rack_line;
    RackType rack = RackType::eight_ball;
    std::optional<std::uint64_t> rack_seed;
    std::optional<int> strike_line;
    Strike strike;
    std::vector<BallLine> balls;
    /// The game directives, checked against each other and the balls in `build`.
    GameContext game;
    /// Directives that may appear once ("table", "param R", ...) and the line that gave them.
    std::map<std::string, int, std::less<>> given;
};

std::vector<Line> split_lines(std::string_view text) {
    std::vector<Line> lines;
    for (const TextLine& text_line : text_lines(text)) {
        Line line{text_line.number, split_fields(strip_comment(text_line.text))};
        if (!line.fields.empty())
            lines.push_back(std::move(line));
    }
    return lines;
}

std::string quoted(std::string_view text) {
    return "'" + std::string(text) + "'";
}

/// Refuses a line with fewer than `min` or more than `max` fields after the name.
Problem arity(const Line& line, std::size_t min, std::size_t max, std::string_view usage) {
    if (line.arguments() < min)
        return "missing field (usage: " + std::string(usage) + ")";
    if (line.arguments() > max)
        return "extra field " + quoted(line.arg(max)) + " (usage: " + std::string(usage) + ")";
    return {};
}

/// Reads a finite number into `out`; `what` names the field in the message.
Problem number(std::string_view text, std::string_view what, double& out) {
    const std::optional<double> value = parse_double(text);
    if (!value)
        return std::string(what) + " " + quoted(text) + " is not a number";
    if (!std::isfinite(*value))
        return std::string(what) + " " + quoted(text) + " is not finite";
    out = *value;
    return {};
}

/// Refuses a second directive of a kind that may appear only once.
Problem once(Draft& draft, const std::string& key, const Line& line) {
    const auto [it, inserted] = draft.given.emplace(key, line.number);
    if (inserted)
        return {};
    return "more than one " + quoted(key) + " line (the first is line " +
           std::to_string(it->second) + ")";
}

Problem parse_table(const Line& line, Draft& draft) {
    if (Problem p = arity(line, 1, 1, "table 9ft|8ft|7ft|snooker"))
        return p;
    if (Problem p = once(draft, "table", line))
        return p;
    const std::optional<TableSize> size = parse_table_size(line.arg(0));
    if (!size)
        return "unknown table size " + quoted(line.arg(0)) + " (expected 9ft, 8ft, 7ft or snooker)";
    draft.setup.table = *size;
    return {};
}

/// `collision` and `cushion` both choose a model by its name in `names`.
template <class Model, std::size_t N>
Problem parse_model(const Line& line, Draft& draft, Model& out, const NameRow<Model> (&names)[N],
                    const char* usage) {
    if (Problem p = arity(line, 1, 1, usage))
        return p;
    const std::string key(line.fields[0]);
    if (Problem p = once(draft, key, line))
        return p;
    const std::optional<Model> model = parse_name(names, line.arg(0));
    if (!model)
        return "unknown " + key + " model " + quoted(line.arg(0)) + " (expected " +
               names_or_list(names) + ")";
    out = *model;
    return {};
}

Problem parse_collision(const Line& line, Draft& draft) {
    return parse_model(line, draft, draft.setup.physics.collision, collision_model_names,
                       "collision physical|ideal");
}

Problem parse_cushion(const Line& line, Draft& draft) {
    return parse_model(line, draft, draft.setup.physics.cushion, cushion_model_names,
                       "cushion physical|ideal|mirror|stronge");
}

Problem parse_friction(const Line& line, Draft& draft) {
    constexpr const char* usage = "friction physical | decay K | constant A | combined K A";
    if (Problem p = arity(line, 1, 3, usage))
        return p;
    if (Problem p = once(draft, "friction", line))
        return p;
    const auto model = termpool::parse_friction(std::span(line.fields).subspan(1));
    if (const auto* friction = std::get_if<FrictionModel>(&model)) {
        draft.setup.physics.friction = *friction;
        return {};
    }
    return friction_problem_text(std::get<FrictionProblem>(model),
                                 std::span(line.fields).subspan(1), usage);
}

/// The line of a directive that may appear once, if it was given.
std::optional<int> line_of(const Draft& draft, std::string_view key) {
    const auto it = draft.given.find(key);
    if (it == draft.given.end())
        return std::nullopt;
    return it->second;
}

Problem parse_param(const Line& line, Draft& draft) {
    if (Problem p = arity(line, 2, 2, "param NAME VALUE"))
        return p;
    const std::string_view name = line.arg(0);
    const bool known =
        std::find(std::begin(physics_parameter_names), std::end(physics_parameter_names), name) !=
        std::end(physics_parameter_names);
    if (known)
        if (Problem p = once(draft, "param " + std::string(name), line))
            return p;
    double value = 0;
    if (known)
        if (Problem p = number(line.arg(1), name, value))
            return p;
    if (name == "u_b")
        if (const std::optional<int> throw_line = line_of(draft, "throw"))
            return "'param u_b' cannot go with 'throw' (line " + std::to_string(*throw_line) +
                   "): both set the ball-ball friction";
    // The core's check, so that a script and a scenario are told the same.
    return set_physics_parameter(draft.setup.physics, name, value);
}

/// Reads a non-negative ball-friction constant of a `throw` line.
Problem friction_constant(std::string_view text, std::string_view what, double& out) {
    if (Problem p = number(text, what, out))
        return p;
    if (out < 0)
        return std::string(what) + " must be >= 0 (got " + std::string(text) + ")";
    return {};
}

Problem parse_throw(const Line& line, Draft& draft) {
    constexpr const char* usage = "throw fit [A B C] | throw constant U";
    if (Problem p = arity(line, 1, 4, usage))
        return p;
    if (Problem p = once(draft, "throw", line))
        return p;
    if (const std::optional<int> param_line = line_of(draft, "param u_b"))
        return "'throw' cannot go with 'param u_b' (line " + std::to_string(*param_line) +
               "): both set the ball-ball friction";
    BallFriction& friction = draft.setup.physics.ball_friction;
    const std::optional<BallFrictionModel> model =
        parse_name(ball_friction_model_names, line.arg(0));
    if (!model)
        return "unknown throw model " + quoted(line.arg(0)) + " (expected fit or constant)";
    if (*model == BallFrictionModel::constant) {
        if (Problem p = arity(line, 2, 2, usage))
            return p;
        friction.model = BallFrictionModel::constant;
        return friction_constant(line.arg(1), "u_b", friction.constant);
    }
    if (line.arguments() == 2 || line.arguments() == 3)
        return arity(line, 4, 4, usage);
    friction.model = BallFrictionModel::fit;
    if (line.arguments() == 1)
        return {};
    if (Problem p = friction_constant(line.arg(1), "fit constant A", friction.a))
        return p;
    if (Problem p = friction_constant(line.arg(2), "fit constant B", friction.b))
        return p;
    return friction_constant(line.arg(3), "fit constant C", friction.c);
}

Problem parse_ball(const Line& line, Draft& draft) {
    if (Problem p = arity(line, 3, 4, "ball ID X Y [mass=KG]"))
        return p;
    const std::optional<long long> id = parse_integer(line.arg(0));
    if (!id)
        return "ball id " + quoted(line.arg(0)) + " is not an integer";
    // Ids 16..21 (snooker's colours) need the snooker table, which a later line may give:
    // `build` refuses them on a pool table.
    const bool snooker = draft.setup.table == TableSize::snooker;
    if (*id < 0 || *id > snooker_last_id)
        return "ball id " + std::to_string(*id) + " is outside " + ball_id_range(snooker);
    BallLine ball{line.number, {}, false};
    ball.ball.id = static_cast<int>(*id);
    for (const BallLine& other : draft.balls) {
        if (other.ball.id == ball.ball.id)
            return "duplicate ball " + std::to_string(*id) + " (already placed on line " +
                   std::to_string(other.line) + ")";
    }
    if (Problem p = number(line.arg(1), "x", ball.ball.position.x))
        return p;
    if (Problem p = number(line.arg(2), "y", ball.ball.position.y))
        return p;
    if (line.arguments() == 4) {
        constexpr std::string_view prefix = "mass=";
        const std::string_view field = line.arg(3);
        if (!field.starts_with(prefix))
            return "unknown field " + quoted(field) + " (expected mass=KG)";
        if (Problem p = number(field.substr(prefix.size()), "mass", ball.ball.mass))
            return p;
        if (ball.ball.mass <= 0)
            return "mass must be > 0 (got " + std::string(field.substr(prefix.size())) + ")";
        ball.has_mass = true;
    }
    draft.balls.push_back(ball);
    return {};
}

Problem parse_rack(const Line& line, Draft& draft) {
    if (Problem p = arity(line, 1, 2, "rack 8ball|9ball|10ball|snooker [SEED]"))
        return p;
    if (Problem p = once(draft, "rack", line))
        return p;
    const std::optional<RackType> rack = parse_name(rack_type_names, line.arg(0));
    if (!rack)
        return "unknown rack " + quoted(line.arg(0)) +
               " (expected 8ball, 9ball, 10ball or snooker)";
    draft.rack = *rack;
    if (line.arguments() == 2) {
        draft.rack_seed = parse_uint64(line.arg(1));
        if (!draft.rack_seed)
            return "seed " + quoted(line.arg(1)) + " is not an unsigned 64-bit integer";
    }
    draft.rack_line = line.number;
    return {};
}

Problem parse_strike(const Line& line, Draft& draft) {
    constexpr const char* usage = "strike V PHI [A B [E]]";
    if (Problem p = arity(line, 2, 5, usage))
        return p;
    if (line.arguments() == 3)
        return arity(line, 4, 4, usage);
    if (Problem p = once(draft, "strike", line))
        return p;
    Strike& s = draft.strike;
    if (Problem p = number(line.arg(0), "speed", s.speed))
        return p;
    if (Problem p = number(line.arg(1), "angle", s.angle_deg))
        return p;
    if (line.arguments() >= 4) {
        if (Problem p = number(line.arg(2), "side offset", s.side))
            return p;
        if (Problem p = number(line.arg(3), "follow offset", s.follow))
            return p;
    }
    if (line.arguments() == 5)
        if (Problem p = number(line.arg(4), "elevation", s.elevation_deg))
            return p;
    // The ranges are the core's (strike_problem), in the words every caller is given; the
    // jump check needs the physics of later lines, so build() asks it all once they are read.
    draft.strike_line = line.number;
    return {};
}

Problem parse_cue(const Line& line, Draft& draft) {
    if (Problem p = arity(line, 1, 1, "cue standard|low-deflection|none|KG"))
        return p;
    if (Problem p = once(draft, "cue", line))
        return p;
    double& end_mass = draft.setup.physics.cue_end_mass;
    const std::string_view word = line.arg(0);
    if (const std::optional<double> named = parse_name(cue_names, word)) {
        end_mass = *named;
    } else {
        if (!parse_double(word))
            return "unknown cue " + quoted(word) +
                   " (expected standard, low-deflection, none or an end mass in kg)";
        if (Problem p = number(word, "cue end mass", end_mass))
            return p;
        if (end_mass < 0)
            return "cue end mass must be >= 0 (got " + std::string(word) + ")";
    }
    return {};
}

Problem parse_game(const Line& line, Draft& draft) {
    if (Problem p = arity(line, 1, 1, "game 8ball|8ball-bar|9ball|10ball"))
        return p;
    if (Problem p = once(draft, "game", line))
        return p;
    const std::optional<GameType> type = parse_game_type(std::string(line.arg(0)));
    // Snooker's referee needs a score sheet a scenario cannot state: it is played in a match.
    if (!type || game_row(*type).scoring == Scoring::points)
        return "unknown game " + quoted(line.arg(0)) +
               " (expected 8ball, 8ball-bar, 9ball or 10ball)";
    draft.setup.game = *type;
    return {};
}

Problem parse_shooter(const Line& line, Draft& draft) {
    if (Problem p = arity(line, 1, 1, "shooter 1|2"))
        return p;
    if (Problem p = once(draft, "shooter", line))
        return p;
    if (line.arg(0) == "1") {
        draft.game.shooter = 1;
    } else if (line.arg(0) == "2") {
        draft.game.shooter = 2;
    } else {
        return "shooter " + quoted(line.arg(0)) + " is not 1 or 2";
    }
    return {};
}

/// The text of `groups` for a group of player 1.
std::string groups_text(Group group) {
    return name_of(player1_group_names, group);
}

Problem parse_groups(const Line& line, Draft& draft) {
    if (Problem p = arity(line, 1, 1, "groups open|1=solids|1=stripes"))
        return p;
    if (Problem p = once(draft, "groups", line))
        return p;
    if (const std::optional<Group> group = parse_name(player1_group_names, line.arg(0))) {
        draft.game.player1_group = *group;
        return {};
    }
    return "unknown groups " + quoted(line.arg(0)) + " (expected open, 1=solids or 1=stripes)";
}

Problem parse_break(const Line& line, Draft& draft) {
    if (Problem p = arity(line, 0, 0, "break"))
        return p;
    if (Problem p = once(draft, "break", line))
        return p;
    draft.game.is_break = true;
    return {};
}

Problem parse_call(const Line& line, Draft& draft) {
    constexpr const char* usage = "call BALL POCKET | call safety";
    if (Problem p = arity(line, 1, 2, usage))
        return p;
    if (Problem p = once(draft, "call", line))
        return p;
    Call& call = draft.game.call;
    if (line.arg(0) == "safety") {
        call.safety = true;
        return arity(line, 1, 1, usage);
    }
    if (Problem p = arity(line, 2, 2, usage))
        return p;
    const std::optional<long long> ball = parse_integer(line.arg(0));
    if (!ball)
        return "called ball " + quoted(line.arg(0)) + " is not an integer";
    if (*ball == 0)
        return "the cue ball (0) cannot be called; call an object ball 1..15";
    if (*ball < 1 || *ball > 15)
        return "called ball " + std::to_string(*ball) + " is outside 1..15";
    const std::optional<long long> pocket = parse_integer(line.arg(1));
    if (!pocket)
        return "called pocket " + quoted(line.arg(1)) + " is not an integer";
    if (*pocket < 1 || *pocket > 6)
        return "called pocket " + std::to_string(*pocket) + " is outside 1..6";
    call.ball = static_cast<int>(*ball);
    call.pocket = static_cast<int>(*pocket);
    return {};
}

Problem parse_push_out(const Line& line, Draft& draft) {
    if (Problem p = arity(line, 0, 0, "push-out"))
        return p;
    if (Problem p = once(draft, "push-out", line))
        return p;
    draft.game.push_out = true;
    return {};
}

using Handler = Problem (*)(const Line&, Draft&);

struct Directive {
    std::string_view name;
    Handler handler;
};

constexpr Directive directives[] = {
    {"table", parse_table},       {"collision", parse_collision}, {"cushion", parse_cushion},
    {"friction", parse_friction}, {"param", parse_param},         {"ball", parse_ball},
    {"rack", parse_rack},         {"strike", parse_strike},       {"game", parse_game},
    {"shooter", parse_shooter},   {"groups", parse_groups},       {"break", parse_break},
    {"call", parse_call},         {"push-out", parse_push_out},   {"cue", parse_cue},
    {"throw", parse_throw},
};

/// The directives that give a scenario a game context, in the order they are documented.
constexpr std::string_view context_directives[] = {"game",  "shooter", "groups",
                                                   "break", "call",    "push-out"};

/// A ball about to go on the table, with the line that put it there.
struct Placed {
    int line = 0;
    Ball ball;
    bool from_rack = false;
};

std::string describe(const Placed& p) {
    return (p.from_rack ? "rack ball " : "ball ") + std::to_string(p.ball.id);
}

/// Every ball of the ball lines and the rack, or the first duplicate between the two.
std::variant<std::vector<Placed>, ScenarioError> gather_balls(const Draft& draft,
                                                              const Scenario& scenario) {
    std::vector<Placed> placed;
    for (const BallLine& b : draft.balls) {
        Placed p{b.line, b.ball, false};
        // The default mass is known only now that every `param m` has been read.
        if (!b.has_mass)
            p.ball.mass = scenario.setup.physics.ball_mass;
        placed.push_back(p);
    }
    if (!draft.rack_line)
        return placed;
    const int rack_line = *draft.rack_line;
    for (const Ball& ball :
         make_rack(scenario.table, scenario.setup.physics, draft.rack, draft.rack_seed)) {
        const auto line = std::find_if(draft.balls.begin(), draft.balls.end(),
                                       [&](const BallLine& b) { return b.ball.id == ball.id; });
        if (line == draft.balls.end()) {
            placed.push_back({rack_line, ball, true});
            continue;
        }
        if (ball.id == 0)
            continue; // a `ball 0` line moves the rack's cue ball
        const std::string id = std::to_string(ball.id);
        if (line->line > rack_line)
            return ScenarioError{line->line, "duplicate ball " + id +
                                                 " (already in the rack on line " +
                                                 std::to_string(rack_line) + ")"};
        return ScenarioError{rack_line, "duplicate ball " + id + ": the rack places it, but line " +
                                            std::to_string(line->line) + " already did"};
    }
    return placed;
}

/// Checks the positions in line order, so that an error names the later of two lines (the
/// core's check, layout_problem, in the scenario's words).
std::optional<ScenarioError> check_positions(std::vector<Placed>& placed,
                                             const Scenario& scenario) {
    std::stable_sort(placed.begin(), placed.end(),
                     [](const Placed& a, const Placed& b) { return a.line < b.line; });
    std::vector<Ball> balls;
    for (const Placed& p : placed)
        balls.push_back(p.ball);
    const auto problem = layout_problem(scenario.table, balls, scenario.setup.physics.ball_radius);
    if (!problem)
        return std::nullopt;
    // The core's words; a ball is named as its line gave it, and an earlier one by its line.
    const auto name = [&](std::size_t index, bool other) {
        const Placed& q = placed[index];
        const bool elsewhere = other && q.line != placed[problem->ball].line;
        return describe(q) + (elsewhere ? " (line " + std::to_string(q.line) + ")" : "");
    };
    return ScenarioError{placed[problem->ball].line, layout_problem_text(*problem, balls, name)};
}

/// One side of a conflict between two directives: how to quote it and where it is.
struct Said {
    std::string text;
    int line = 0;
};

/// Two directives that cannot go together, reported at the later one; the message points back
/// to the earlier.
ScenarioError conflict(Said a, Said b, std::string_view why) {
    const bool a_first = a.line < b.line;
    std::string first = quoted(a.text), second = quoted(b.text);
    (a_first ? first : second) += " (line " + std::to_string(std::min(a.line, b.line)) + ")";
    return ScenarioError{std::max(a.line, b.line),
                         first + " cannot go with " + second + ": " + std::string(why)};
}

/// True when any game directive was given.
bool has_game_context(const Draft& draft) {
    return std::any_of(std::begin(context_directives), std::end(context_directives),
                       [&](std::string_view key) { return line_of(draft, key).has_value(); });
}

/// The largest ball id the referee of `game` knows.
int last_ball_of(GameType game) {
    return rack_last_ball(game_row(game).rack);
}

/// The titles of the games with a push-out ("9-ball and 10-ball"), or their names as a
/// directive gives them ("'game 9ball' or 'game 10ball'").
std::string push_out_games(bool directives) {
    std::vector<std::string> games;
    for (const GameRow& row : game_registry().rows())
        if (row.push_out)
            games.push_back(directives ? "'game " + std::string(row.name) + "'" : row.title);
    std::string text;
    for (std::size_t i = 0; i < games.size(); ++i)
        text += (i == 0                  ? ""
                 : i + 1 == games.size() ? (directives ? " or " : " and ")
                                         : ", ") +
                games[i];
    return text;
}

/// Checks the game directives against each other, the balls and the strike.
std::optional<ScenarioError> check_game(const Draft& draft, const std::vector<Placed>& placed) {
    const GameContext& game = draft.game;
    const std::optional<int> game_line = line_of(draft, "game");
    const std::optional<int> groups_line = line_of(draft, "groups");
    const std::optional<int> call_line = line_of(draft, "call");
    const std::optional<int> break_line = line_of(draft, "break");
    const Said game_said{"game " + std::string(game_type_name(draft.setup.game)),
                         game_line.value_or(0)};

    if (groups_line && break_line)
        return conflict({"groups " + groups_text(game.player1_group), *groups_line},
                        {"break", *break_line}, "the table is open at the break");
    const GameRow& row = game_row(draft.setup.game);
    if (!row.groups && groups_line && game.player1_group != Group::open)
        return conflict({"groups " + groups_text(game.player1_group), *groups_line}, game_said,
                        std::string(row.title) + " has no groups");
    // game_line is set: a game without calls is never the default.
    if (row.calls == CallRule::nothing && call_line)
        return conflict({"call", *call_line}, game_said,
                        std::string(row.title) + " shots are not called");
    if (const std::optional<int> push_line = line_of(draft, "push-out")) {
        if (!row.push_out)
            return game_line ? conflict({"push-out", *push_line}, game_said,
                                        "the push-out is a " + push_out_games(false) + " rule")
                             : ScenarioError{*push_line, "push-out needs " + push_out_games(true)};
        if (break_line)
            return conflict({"push-out", *push_line}, {"break", *break_line},
                            "the push-out is the shot after the break");
    }
    // A pool referee has no verdict on a snooker colour.
    if (has_game_context(draft)) {
        for (const Placed& p : placed) {
            if (p.ball.id <= last_ball_of(draft.setup.game))
                continue;
            const std::string why = "the " + std::string(game_type_name(draft.setup.game)) +
                                    " referee judges balls 0.." +
                                    std::to_string(last_ball_of(draft.setup.game)) + " only";
            return game_line
                       ? conflict({describe(p), p.line}, game_said, why)
                       : ScenarioError{p.line, describe(p) + " needs a game that has it: " + why};
        }
    }
    if (call_line && game.call.ball != 0) {
        const bool on_table = std::any_of(placed.begin(), placed.end(), [&](const Placed& p) {
            return p.ball.id == game.call.ball;
        });
        if (!on_table)
            return ScenarioError{*call_line, "called ball " + std::to_string(game.call.ball) +
                                                 " is not on the table"};
    }
    if (!draft.strike_line) {
        // At the first game directive: the whole context is what has nothing to apply to.
        std::optional<Said> first;
        for (const std::string_view key : context_directives) {
            const std::optional<int> line = line_of(draft, key);
            if (line && (!first || *line < first->line))
                first = Said{std::string(key), *line};
        }
        if (first)
            return ScenarioError{first->line,
                                 quoted(first->text) + " without a strike: nothing to judge"};
    }
    return std::nullopt;
}

/// The first ball line with an id the table does not take (16..21 on a pool table).
std::optional<ScenarioError> check_ball_ids(const Draft& draft) {
    if (draft.setup.table == TableSize::snooker)
        return std::nullopt;
    for (const BallLine& b : draft.balls)
        if (b.ball.id > pool_last_id)
            return ScenarioError{b.line, "ball id " + std::to_string(b.ball.id) + " is outside " +
                                             ball_id_range(false)};
    return std::nullopt;
}

/// The physics of the scenario: its directives on the balls of its table (snooker balls on the
/// snooker table), but a radius or mass a `param` line gave stays.
PhysicsParams scenario_physics(const Draft& draft) {
    PhysicsParams physics = draft.setup.physics;
    const PhysicsParams table_balls = physics_for_table(draft.setup.table, physics);
    if (!line_of(draft, "param R"))
        physics.ball_radius = table_balls.ball_radius;
    if (!line_of(draft, "param m"))
        physics.ball_mass = table_balls.ball_mass;
    return physics;
}

/// Puts the checked directives together: the table and balls follow the final parameters.
ScenarioResult build(const Draft& draft) {
    if (auto error = check_ball_ids(draft))
        return *error;
    Scenario scenario;
    scenario.setup = draft.setup;
    scenario.setup.physics = scenario_physics(draft);
    // Built for the radius in the scenario's physics, which `param R` may have set.
    scenario.table = make_table(scenario.setup.table, scenario.setup.physics.ball_radius);
    auto gathered = gather_balls(draft, scenario);
    if (auto* error = std::get_if<ScenarioError>(&gathered))
        return *error;
    std::vector<Placed>& placed = std::get<std::vector<Placed>>(gathered);
    if (auto error = check_positions(placed, scenario))
        return *error;

    const bool has_cue =
        std::any_of(placed.begin(), placed.end(), [](const Placed& p) { return p.ball.id == 0; });
    if (draft.strike_line && !has_cue)
        return ScenarioError{*draft.strike_line, "strike without a cue ball (no ball 0)"};
    // Only now are the ball's size, gravity and the cue final, on which the jump limit depends.
    if (draft.strike_line) {
        if (const auto problem = strike_problem(draft.strike, scenario.setup.physics))
            return ScenarioError{*draft.strike_line, *problem};
    }

    if (auto error = check_game(draft, placed))
        return *error;
    if (has_game_context(draft))
        scenario.game = draft.game;

    std::sort(placed.begin(), placed.end(),
              [](const Placed& a, const Placed& b) { return a.ball.id < b.ball.id; });
    for (const Placed& p : placed)
        scenario.balls.push_back(p.ball);
    if (draft.strike_line)
        scenario.strike = draft.strike;
    return scenario;
}

} // namespace

ScenarioResult parse_scenario(std::string_view text) {
    Draft draft;
    for (const Line& line : split_lines(text)) {
        const std::string_view name = line.fields[0];
        const auto directive = std::find_if(std::begin(directives), std::end(directives),
                                            [&](const Directive& d) { return d.name == name; });
        if (directive == std::end(directives))
            return ScenarioError{line.number, "unknown directive " + quoted(name)};
        if (Problem p = directive->handler(line, draft))
            return ScenarioError{line.number, *p};
    }
    return build(draft);
}

} // namespace termpool::cli
