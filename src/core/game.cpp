// The referee's state machine: racks, ball in hand, choices, and the parts of judging a shot
// that every game shares. The rules of each game are in eight_ball.cpp, nine_ball.cpp and
// ten_ball.cpp and snooker.cpp.
#include <algorithm>
#include <termpool/rack.hpp>
#include <termpool/snooker_layout.hpp>
#include <termpool/spots.hpp>

#include "shot_facts.hpp"

namespace termpool {

Game::Game(GameType type, const Table& table, const PhysicsParams& params, int breaker,
           std::uint64_t seed)
    : type_(type), table_(table), params_(params), seed_(seed) {
    rerack(breaker);
}

Game Game::from_position(GameType type, const Table& table, const PhysicsParams& params,
                         std::vector<Ball> balls, int shooter, Group player1_group, bool is_break,
                         bool push_out_allowed) {
    Game g;
    g.type_ = type;
    g.table_ = table;
    g.params_ = params;
    g.balls_ = std::move(balls);
    g.shooter_ = shooter;
    g.breaker_ = shooter;
    g.is_break_ = is_break;
    g.player1_group_ = player1_group;
    g.ball_in_hand_ = BallInHand::none;
    g.push_out_allowed_ = push_out_allowed;
    if (type == GameType::snooker) {
        const bool reds = std::ranges::any_of(g.balls_, [](const Ball& b) {
            return is_snooker_red(b.id) && b.state != MotionState::pocketed;
        });
        g.snooker_.ball_on = reds ? BallOn::red : BallOn::in_order;
    }
    return g;
}

Game Game::from_snooker_position(const Table& table, const PhysicsParams& params,
                                 std::vector<Ball> balls, int shooter, const SnookerState& state,
                                 BallInHand ball_in_hand) {
    Game g = from_position(GameType::snooker, table, params, std::move(balls), shooter, Group::open,
                           false);
    g.snooker_ = state;
    g.ball_in_hand_ = ball_in_hand;
    return g;
}

RackType game_rack(GameType type) {
    switch (type) {
    case GameType::eight_ball:
    case GameType::eight_ball_bar:
        return RackType::eight_ball;
    case GameType::nine_ball:
        return RackType::nine_ball;
    case GameType::ten_ball:
        return RackType::ten_ball;
    case GameType::snooker:
        return RackType::snooker;
    }
    return RackType::eight_ball;
}

void Game::rerack(int new_breaker) {
    const RackType rack = game_rack(type_);
    // Each rack of a game gets its own seed, so re-racks differ but replay the same.
    balls_ = make_rack(table_, params_, rack, game_rack_seed(seed_, racks_));
    ++racks_;
    breaker_ = shooter_ = new_breaker;
    is_break_ = true;
    player1_group_ = Group::open;
    ball_in_hand_ = type_ == GameType::snooker ? BallInHand::d : BallInHand::kitchen;
    chooser_ = 0;
    choices_.clear();
    snooker_ = {};
    free_ball_offered_ = false;
    push_out_allowed_ = false;
    fouls_in_a_row_[0] = fouls_in_a_row_[1] = 0;
    turns_without_progress_ = 0;
    stalemate_turns_left_ = -1;
}

Group Game::group_of(int player) const {
    if (player1_group_ == Group::open)
        return Group::open;
    if (player == 1)
        return player1_group_;
    return player1_group_ == Group::solids ? Group::stripes : Group::solids;
}

bool Game::ball_on_table(int id) const {
    return std::any_of(balls_.begin(), balls_.end(), [id](const Ball& b) {
        return b.id == id && b.state != MotionState::pocketed;
    });
}

std::vector<int> Game::legal_targets() const {
    std::vector<int> on_table;
    for (const Ball& b : balls_)
        if (b.id != 0 && b.state != MotionState::pocketed)
            on_table.push_back(b.id);
    std::sort(on_table.begin(), on_table.end());
    if (type_ == GameType::snooker)
        return snooker_.free_ball ? on_table : balls_on();
    if (type_ == GameType::nine_ball || type_ == GameType::ten_ball || on_table.empty())
        return on_table.empty() ? on_table : std::vector<int>{on_table.front()};
    const Group group = group_of(shooter_);
    std::vector<int> targets;
    for (const int id : on_table) {
        const bool own =
            group == Group::open ? id != 8 : std::ranges::count(group_balls(group), id) > 0;
        if (own)
            targets.push_back(id);
    }
    if (targets.empty() && group != Group::open)
        targets.push_back(8);
    if (targets.empty())
        targets = on_table; // only the 8 left on an open table
    return targets;
}

bool Game::legal_placement(Vec2 p) const {
    if (ball_in_hand_ == BallInHand::none)
        return false;
    const double R = params_.ball_radius;
    if (!on_playing_surface(table_, p, R))
        return false;
    if (ball_in_hand_ == BallInHand::kitchen && p.x > table_.head_string_x())
        return false;
    if (ball_in_hand_ == BallInHand::d && !in_snooker_d(table_, p))
        return false;
    return ball_touching(balls_, p, R, 0) < 0;
}

std::vector<Vec2> Game::legal_placements(int per_axis) const {
    std::vector<Vec2> spots;
    const double R = params_.ball_radius;
    const double x_max = ball_in_hand_ == BallInHand::kitchen ? table_.head_string_x()
                         : ball_in_hand_ == BallInHand::d     ? snooker_baulk_x(table_)
                                                              : table_.length - R;
    for (int i = 0; i < per_axis; ++i) {
        for (int j = 0; j < per_axis; ++j) {
            const Vec2 p{R + (x_max - R) * (i + 0.5) / per_axis,
                         R + (table_.width - 2 * R) * (j + 0.5) / per_axis};
            if (legal_placement(p))
                spots.push_back(p);
        }
    }
    return spots;
}

bool Game::place_cue_ball(Vec2 p) {
    if (winner_ != 0 || chooser_ != 0 || !legal_placement(p))
        return false;
    for (Ball& b : balls_) {
        if (b.id != 0)
            continue;
        b.mass = params_.cue_mass();
        set_at_rest(b, p);
        return true;
    }
    Ball cue;
    cue.mass = params_.cue_mass();
    cue.position = p;
    balls_.insert(balls_.begin(), cue);
    return true;
}

void Game::spot_ball(int id) {
    // The foot spot, or the nearest free point behind it on the long string, or else in front.
    const Vec2 foot = table_.foot_spot();
    const Vec2 spot =
        free_spot_on_string(table_, balls_, foot, params_.ball_radius, id).value_or(foot);
    for (Ball& b : balls_)
        if (b.id == id)
            set_at_rest(b, spot);
}

bool Game::choose(Choice choice) {
    if (chooser_ == 0 || std::ranges::count(choices_, choice) == 0)
        return false;
    const int who = chooser_;
    chooser_ = 0;
    choices_.clear();
    const bool free_ball = free_ball_offered_;
    free_ball_offered_ = false;
    switch (choice) {
    case Choice::play_on:
    case Choice::shoot:
        shooter_ = who;
        is_break_ = false;
        snooker_.free_ball = free_ball;
        snooker_.misses[opponent(who) - 1] = 0; // the three-miss count needs the balls replaced
        break;
    case Choice::offender_plays:
        shooter_ = opponent(who);
        snooker_.misses[opponent(who) - 1] = 0;
        break;
    case Choice::replace_and_replay:
        // The foul's points stay given; the balls and the ball on go back as they were.
        balls_ = before_shot_.balls;
        ball_in_hand_ = before_shot_.ball_in_hand;
        snooker_.ball_on = before_shot_.state.ball_on;
        snooker_.free_ball = before_shot_.state.free_ball;
        shooter_ = opponent(who);
        break;
    case Choice::concede:
        break; // never owed: see concede()
    case Choice::re_rack:
        rerack(who);
        break;
    case Choice::re_break:
        rerack(breaker_);
        break;
    case Choice::spot_eight:
        spot_ball(8);
        shooter_ = who;
        is_break_ = false;
        break;
    case Choice::take_solids:
    case Choice::take_stripes: {
        const Group g = choice == Choice::take_solids ? Group::solids : Group::stripes;
        player1_group_ = who == 1 ? g : (g == Group::solids ? Group::stripes : Group::solids);
        shooter_ = who;
        break;
    }
    case Choice::pass_back:
        shooter_ = pusher_;
        break;
    }
    return true;
}

void Game::finish_turn(Verdict& v, bool progress) {
    // Stalemate: after many turns without a ball dropping, three more turns each, then the
    // original breaker breaks a new rack.
    if (winner_ == 0 && chooser_ == 0 && type_ != GameType::snooker) {
        turns_without_progress_ = progress ? 0 : turns_without_progress_ + 1;
        if (progress) {
            stalemate_turns_left_ = -1;
        } else if (stalemate_turns_left_ > 0) {
            if (--stalemate_turns_left_ == 0) {
                rerack(breaker_);
                v.stalemate_rerack = true;
            }
        } else if (turns_without_progress_ >= stalemate_warning_turns) {
            stalemate_turns_left_ = 6;
        }
    }
    v.player1_group = player1_group_;
    v.next_shooter = chooser_ != 0 ? chooser_ : shooter_;
    v.ball_in_hand = ball_in_hand_;
    v.chooser = chooser_;
    v.choices = choices_;
    v.winner = winner_;
    v.reason = reason_;
}

bool Game::ready_to_shoot() const {
    const auto cue = std::find_if(balls_.begin(), balls_.end(), [](const Ball& b) {
        return b.id == 0 && b.state != MotionState::pocketed;
    });
    return winner_ == 0 && chooser_ == 0 && cue != balls_.end() &&
           (ball_in_hand_ == BallInHand::none || legal_placement(cue->position));
}

Verdict Game::apply(const ShotCall& call, const ShotResult& result) {
    Verdict refused;
    refused.next_shooter = shooter_;
    refused.player1_group = player1_group_;
    refused.ball_in_hand = ball_in_hand_;
    if (!ready_to_shoot() || result.balls.size() != balls_.size())
        return refused;

    Facts facts = Facts::from(result.events);
    const bool snooker = type_ == GameType::snooker;
    facts.targets = snooker ? snooker_targets(call) : legal_targets();
    facts.prefer_legal_first_contact();
    if (snooker) {
        before_shot_ = {balls_, ball_in_hand_, snooker_};
        facts.touching = touching_ball();
        facts.snookered_before = shooter_snookered();
    }
    const Group group = group_of(shooter_);
    facts.group_cleared =
        group != Group::open &&
        std::ranges::none_of(group_balls(group), [&](int id) { return ball_on_table(id); });
    balls_ = result.balls;
    for (Ball& b : balls_) {
        if (facts.left_table(b.id)) {
            b.state = MotionState::pocketed;
            b.pocket = 0;
            b.velocity = {};
            b.angular_velocity = {};
        }
    }
    ball_in_hand_ = BallInHand::none;
    Verdict v = snooker                        ? judge_snooker(call, facts)
                : type_ == GameType::nine_ball ? judge_nine(call, facts)
                : type_ == GameType::ten_ball  ? judge_ten(call, facts)
                                               : judge_eight(call, facts);
    v.first_contact = facts.first_contact;
    v.pocketed = facts.pocketed;
    v.fouls.erase(std::remove(v.fouls.begin(), v.fouls.end(), Foul::none), v.fouls.end());
    std::sort(v.fouls.begin(), v.fouls.end());
    v.foul = v.fouls.empty() ? Foul::none : v.fouls.front();
    finish_turn(v, facts.object_ball_dropped());
    return v;
}

Verdict Game::play(const Strike& strike, const ShotCall& call, ShotResult* out) {
    const ShotResult result = simulate_shot(table_, params_, balls_, strike);
    if (out)
        *out = result;
    return apply(call, result);
}

} // namespace termpool
