// The game's state machine: racks, ball in hand, placing the cue ball, the choice owed, and the
// part of judging a shot that every game shares. What a shot or a choice means is the
// referee's (eight_ball.cpp, rotation.cpp, snooker.cpp), found through the game's row.
#include <algorithm>
#include <termpool/game_registry.hpp>
#include <termpool/rack.hpp>
#include <termpool/referee.hpp>
#include <termpool/snooker_layout.hpp>
#include <termpool/spots.hpp>

#include "snooker_referee.hpp"

namespace termpool {

bool GameState::on_table(int id) const {
    return std::ranges::any_of(
        balls, [id](const Ball& b) { return b.id == id && b.state != MotionState::pocketed; });
}

void GameState::rerack(int new_breaker) {
    // Each rack of a game gets its own seed, so re-racks differ but replay the same.
    balls = make_rack(table, params, rack, game_rack_seed(seed, racks));
    ++racks;
    breaker = shooter = new_breaker;
    is_break = true;
    ball_in_hand = break_from;
    chooser = 0;
    choices.clear();
}

void GameState::spot_on_foot_string(int id) {
    const Vec2 foot = table.foot_spot();
    const Vec2 spot =
        free_spot_on_string(table, balls, foot, params.ball_radius, id).value_or(foot);
    for (Ball& b : balls)
        if (b.id == id)
            set_at_rest(b, spot);
}

Game::Game(GameType type, const Table& table, const PhysicsParams& params, int breaker,
           std::uint64_t seed)
    : Game(game_row(type), table, params, breaker, seed) {}

Game::Game(const GameRow& row, const Table& table, const PhysicsParams& params, int breaker,
           std::uint64_t seed)
    : type_(row.type), referee_(row.make_referee()) {
    state_.table = table;
    state_.params = params;
    state_.rack = row.rack;
    state_.break_from = row.break_from;
    state_.seed = seed;
    state_.rerack(breaker);
    referee_->new_rack(state_);
}

namespace {

// A copy of `referee` (none for a game moved from).
std::unique_ptr<Referee> copy_of(const std::unique_ptr<Referee>& referee) {
    return referee ? referee->clone() : nullptr;
}

} // namespace

Game::Game(const Game& other)
    : type_(other.type_), state_(other.state_), referee_(copy_of(other.referee_)) {}

Game& Game::operator=(const Game& other) {
    if (this != &other) {
        type_ = other.type_;
        state_ = other.state_;
        referee_ = copy_of(other.referee_);
    }
    return *this;
}

Game::Game(Game&& other) noexcept = default;
Game& Game::operator=(Game&& other) noexcept = default;
Game::~Game() = default;

Game Game::from_sheet(const GameRow& row, const Table& table, const PhysicsParams& params,
                      std::vector<Ball> balls, int shooter, bool is_break, BallInHand ball_in_hand,
                      const ScoreSheet& sheet) {
    Game g;
    g.type_ = row.type;
    g.referee_ = row.make_referee();
    GameState& s = g.state_;
    s.table = table;
    s.params = params;
    s.rack = row.rack;
    s.break_from = row.break_from;
    s.balls = std::move(balls);
    s.shooter = s.breaker = shooter;
    s.is_break = is_break;
    s.ball_in_hand = ball_in_hand;
    g.referee_->set_up(s, sheet);
    return g;
}

Game Game::from_position(GameType type, const Table& table, const PhysicsParams& params,
                         std::vector<Ball> balls, int shooter, Group player1_group, bool is_break,
                         bool push_out_allowed) {
    ScoreSheet sheet;
    sheet.player1_group = player1_group;
    sheet.push_out_allowed = push_out_allowed;
    // A snooker frame in progress is on a red while there is one (other games ignore it).
    const bool reds = std::ranges::any_of(balls, [](const Ball& b) {
        return is_snooker_red(b.id) && b.state != MotionState::pocketed;
    });
    sheet.frame.ball_on = reds ? BallOn::red : BallOn::in_order;
    return from_sheet(game_row(type), table, params, std::move(balls), shooter, is_break,
                      BallInHand::none, sheet);
}

Game Game::from_snooker_position(const Table& table, const PhysicsParams& params,
                                 std::vector<Ball> balls, int shooter, const SnookerState& state,
                                 BallInHand ball_in_hand) {
    ScoreSheet sheet;
    sheet.frame = state;
    return from_sheet(game_row(GameType::snooker), table, params, std::move(balls), shooter, false,
                      ball_in_hand, sheet);
}

RackType game_rack(GameType type) {
    return game_row(type).rack;
}

ScoreSheet Game::score_sheet() const {
    return referee_->score_sheet(state_);
}

Group Game::group_of(int player) const {
    const Group first = player1_group();
    if (first == Group::open || player == 1)
        return first;
    return first == Group::solids ? Group::stripes : Group::solids;
}

std::vector<int> Game::legal_targets() const {
    return referee_->legal_targets(state_);
}

bool Game::pocket_must_be_called(int ball) const {
    return !state_.is_break && referee_->pocket_must_be_called(state_, ball);
}

std::vector<int> Game::balls_on() const {
    return referee_->balls_on(state_);
}

bool Game::nomination_owed() const {
    return referee_->nomination_owed(state_);
}

namespace {

const SnookerReferee* as_snooker(const Referee& referee) {
    return dynamic_cast<const SnookerReferee*>(&referee);
}

} // namespace

const SnookerState& Game::snooker() const {
    static const SnookerState none;
    const SnookerReferee* s = as_snooker(*referee_);
    return s ? s->frame() : none;
}

int Game::touching_ball() const {
    const SnookerReferee* s = as_snooker(*referee_);
    return s ? s->touching_ball(state_) : -1;
}

bool Game::shooter_snookered() const {
    const SnookerReferee* s = as_snooker(*referee_);
    return s && s->shooter_snookered(state_);
}

bool Game::free_ball_offered() const {
    const SnookerReferee* s = as_snooker(*referee_);
    return s && s->free_ball_offered();
}

int Game::points_remaining() const {
    const SnookerReferee* s = as_snooker(*referee_);
    return s ? s->points_remaining(state_) : 0;
}

bool Game::concede(int player) {
    if (state_.winner != 0 || (player != 1 && player != 2))
        return false;
    return referee_->concede(state_, player);
}

bool Game::legal_placement(Vec2 p) const {
    const GameState& s = state_;
    if (s.ball_in_hand == BallInHand::none)
        return false;
    const double R = s.params.ball_radius;
    if (!on_playing_surface(s.table, p, R))
        return false;
    if (s.ball_in_hand == BallInHand::kitchen && p.x > s.table.head_string_x())
        return false;
    if (s.ball_in_hand == BallInHand::d && !in_snooker_d(s.table, p))
        return false;
    return ball_touching(s.balls, p, R, 0) < 0;
}

std::vector<Vec2> Game::legal_placements(int per_axis) const {
    const GameState& s = state_;
    const Table& table = s.table;
    std::vector<Vec2> spots;
    const double R = s.params.ball_radius;
    const double x_max = s.ball_in_hand == BallInHand::kitchen ? table.head_string_x()
                         : s.ball_in_hand == BallInHand::d     ? snooker_baulk_x(table)
                                                               : table.length - R;
    for (int i = 0; i < per_axis; ++i) {
        for (int j = 0; j < per_axis; ++j) {
            const Vec2 p{R + (x_max - R) * (i + 0.5) / per_axis,
                         R + (table.width - 2 * R) * (j + 0.5) / per_axis};
            if (legal_placement(p))
                spots.push_back(p);
        }
    }
    return spots;
}

bool Game::place_cue_ball(Vec2 p) {
    if (state_.winner != 0 || state_.chooser != 0 || !legal_placement(p))
        return false;
    const double mass = state_.params.cue_mass();
    for (Ball& b : state_.balls) {
        if (b.id != 0)
            continue;
        b.mass = mass;
        set_at_rest(b, p);
        return true;
    }
    Ball cue;
    cue.mass = mass;
    cue.position = p;
    state_.balls.insert(state_.balls.begin(), cue);
    return true;
}

bool Game::choose(Choice choice) {
    if (state_.chooser == 0 || std::ranges::count(state_.choices, choice) == 0)
        return false;
    const int who = state_.chooser;
    state_.chooser = 0;
    state_.choices.clear();
    referee_->choose(state_, who, choice);
    return true;
}

bool Game::ready_to_shoot() const {
    const auto cue = std::ranges::find_if(
        state_.balls, [](const Ball& b) { return b.id == 0 && b.state != MotionState::pocketed; });
    return state_.winner == 0 && state_.chooser == 0 && cue != state_.balls.end() &&
           (state_.ball_in_hand == BallInHand::none || legal_placement(cue->position));
}

Game::ShotPlan Game::plan(const ShotCall& call) const {
    ShotPlan plan;
    plan.ready = ready_to_shoot();
    if (plan.ready)
        plan.targets = referee_->shot_targets(state_, call);
    return plan;
}

Verdict Game::apply(const ShotCall& call, const ShotResult& result) {
    return apply(call, result, plan(call));
}

Verdict Game::apply(const ShotCall& call, const ShotResult& result, const ShotPlan& plan) {
    GameState& s = state_;
    if (!plan.ready || result.balls.size() != s.balls.size()) {
        Verdict refused;
        refused.next_shooter = s.shooter;
        refused.player1_group = player1_group();
        refused.ball_in_hand = s.ball_in_hand;
        return refused;
    }

    ShotFacts facts = ShotFacts::from(result.events);
    facts.targets = plan.targets;
    facts.prefer_legal_first_contact();
    referee_->before_shot(s);
    s.balls = result.balls;
    for (Ball& b : s.balls) {
        if (facts.left_table(b.id)) {
            b.state = MotionState::pocketed;
            b.pocket = 0;
            b.velocity = {};
            b.angular_velocity = {};
        }
    }
    s.ball_in_hand = BallInHand::none;
    Verdict v = referee_->judge(s, call, facts);
    v.first_contact = facts.first_contact;
    v.pocketed = facts.pocketed;
    v.fouls.erase(std::remove(v.fouls.begin(), v.fouls.end(), Foul::none), v.fouls.end());
    std::sort(v.fouls.begin(), v.fouls.end());
    v.foul = v.fouls.empty() ? Foul::none : v.fouls.front();
    v.player1_group = player1_group();
    v.next_shooter = s.chooser != 0 ? s.chooser : s.shooter;
    v.ball_in_hand = s.ball_in_hand;
    v.chooser = s.chooser;
    v.choices = s.choices;
    v.winner = s.winner;
    v.reason = s.reason;
    return v;
}

Verdict Game::play(const Strike& strike, const ShotCall& call, ShotResult* out) {
    const ShotResult result = simulate_shot(table(), params(), balls(), strike);
    if (out)
        *out = result;
    return apply(call, result);
}

} // namespace termpool
