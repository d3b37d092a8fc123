// The computer player's search: ghost-ball aims at every legal target and pocket, at a few
// speeds and spins, each simulated on a copy of the game and scored by the referee.
#include "../support/portable_math.hpp"
#include "../support/random.hpp"
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <termpool/break_off.hpp>
#include <termpool/computer.hpp>
#include <termpool/game_registry.hpp>
#include <termpool/simulator.hpp>
#include <termpool/snooker_layout.hpp>

#include "computer_parts.hpp"
#include "position_play.hpp"
#include "shot_lines.hpp"
#include "snooker_leave.hpp"

namespace termpool {
namespace {

// Execution noise of the computer-pool tournaments, scaled by level: aim (degrees), speed
// (m/s) and tip offsets (0.5 mm, as a fraction of the ball's radius where a strike needs it).
constexpr double sigma_aim_deg = 0.125;
constexpr double sigma_speed = 0.075;
constexpr double sigma_tip_m = 0.0005;
constexpr double break_speed = 12.0;
// The work (ShotTrial::work: events simulated, and set-ups) a decision's searches may do before
// they stop sampling further (each candidate is still tried once): about half a second on one
// core of the development machine, so that a decision with many candidates, long shots and
// spots to compare (the cue ball in hand after a break) stays within a second. Few decisions
// come near it.
constexpr std::uint64_t decision_budget = 700000;

// The tip's noise as a fraction of R: 0.5 mm is a larger part of a snooker ball's radius.
double sigma_tip(const PhysicsParams& params) {
    return sigma_tip_m / params.ball_radius;
}

double noise_scale(Level level) {
    switch (level) {
    case Level::easy:
        return 4;
    case Level::medium:
        return 2;
    case Level::hard:
        return 1;
    case Level::pro:
        return 0.5;
    }
    return 1;
}

// The aim's part of the direction error, degrees at noise scale 1. The tournaments measured the
// direction error as a whole (sigma_aim_deg); now that an error in side turns the ball as well
// (squirt, to first order in the offset), the aim's own part is what is left of it.
double aim_sigma_deg(const PhysicsParams& params) {
    constexpr double small_side = 1e-3;
    const double from_tip = squirt_angle_deg(small_side, params.cue_mass(), params.cue_end_mass) /
                            small_side * sigma_tip(params);
    return std::sqrt(std::max(0.0, sigma_aim_deg * sigma_aim_deg - from_tip * from_tip));
}

// The referee's opinion of a simulated shot, from the shooter's side.
double score(const Verdict& v, int shooter) {
    if (v.winner != 0)
        return v.winner == shooter ? 1000 : -1000;
    double s = 0;
    if (v.foul != Foul::none)
        s -= 60;
    if (v.next_shooter == shooter && v.chooser == 0)
        s += 100;
    for (const int id : v.pocketed)
        if (id != 0)
            s += 5;
    if (v.chooser != 0 && v.chooser != shooter)
        s -= 20;
    return s;
}

// Whether a pot with the cue ball `to_object` behind the object ball and the pocket `to_pocket`
// beyond it is cut thinner than a cosine of 0.34, told without a square root. The cut is at least
// the angle between the two lines (the ghost ball sits 2R further back along the second), so a
// cosine of that angle below 0.33 (about 71 degrees), or past 90 degrees, says so with a margin
// far beyond the rounding. Only for a positive radius and lengths from a nanometre to a
// kilometre, where the squares neither underflow nor overflow; otherwise the full test decides.
// (Inline: asked of every ball and pocket of every sample, it cost as much again as a call.)
inline bool surely_too_thin(Vec2 to_object, Vec2 to_pocket, double R) {
    const double object_squared = length_squared(to_object);
    const double pocket_squared = length_squared(to_pocket);
    if (!(R > 0 && object_squared > 1e-18 && object_squared < 1e6 && pocket_squared > 1e-18 &&
          pocket_squared < 1e6))
        return false;
    const double along = dot(to_object, to_pocket);
    return along <= 0 || along * along < 0.33 * 0.33 * object_squared * pocket_squared;
}

// How good the shooter's next shot looks from here: the best legal ball and pocket with nothing
// in the way, rated 0..1 by how full the cut is and how far the balls travel, times what the
// ball is worth (`weight`).
template <class Weight> double weighted_next_quality(const Game& game, Weight weight) {
    const double R = game.params().ball_radius;
    return best_clear_pot(
        game, [&](int target, const Ball& cue, const Ball& object, int pocket, double best) {
            const Vec2 to_pocket = game.table().pockets[pocket - 1].position - object.position;
            if (surely_too_thin(object.position - cue.position, to_pocket, R))
                return 0.0;
            // normalized() twice, keeping the lengths for the distance factor (the same bits).
            const double pocket_distance = length(to_pocket);
            const Vec2 towards_pocket = pocket_distance > 0 ? to_pocket / pocket_distance : Vec2{};
            const Vec2 ghost = object.position - towards_pocket * (2 * R);
            const Vec2 line = ghost - cue.position;
            const double line_length = length(line);
            const double cut = dot(line_length > 0 ? line / line_length : Vec2{}, towards_pocket);
            if (cut < 0.34)
                return 0.0;
            // A weight of 1 leaves the product's bits as they were without it.
            const double most = weight(target) * cut * cut;
            // The distance factor is at most 1: a pot that cannot beat the best so far skips the
            // exponential, the dearest part (the margin covers its rounding).
            if (most * (1 + 1e-9) <= best)
                return 0.0;
            return most * portable::exp(-(line_length + pocket_distance) / 2.5);
        });
}

// Pool: every legal ball is worth the same.
double next_shot_quality(const Game& game) {
    return weighted_next_quality(game, [](int) { return 1.0; });
}

// Snooker: the best next pot for whoever is on now, each ball weighted by what it is worth (a
// colour after a red: the black before the yellow).
double snooker_next_quality(const Game& game) {
    return weighted_next_quality(game, snooker_ball_weight);
}

// Snooker, easy: a shot's worth from the shooter's side in points scored and given away, and
// the table kept. (The levels above have their own search, computer_snooker.cpp.)
double snooker_points_score(const Verdict& v, int shooter) {
    if (v.winner != 0)
        return v.winner == shooter ? 1000 : -1000;
    const double s = 12.0 * v.points - 12.0 * v.penalty;
    if (v.foul != Foul::none)
        return s - 60 - (v.miss ? 20 : 0);
    return v.next_shooter == shooter ? s + 100 : s;
}

// Turns playing leaves out off for as long as it lives.
class LeavesNotPlayedOut {
public:
    explicit LeavesNotPlayedOut(bool& flag) : flag_(flag), was_(flag) { flag_ = false; }
    ~LeavesNotPlayedOut() { flag_ = was_; }
    LeavesNotPlayedOut(const LeavesNotPlayedOut&) = delete;
    LeavesNotPlayedOut& operator=(const LeavesNotPlayedOut&) = delete;

private:
    bool& flag_;
    bool was_;
};

} // namespace

// The ghost-ball aim sends the object ball along the line of centres, but it leaves a little
// off it (throw, from the balls' friction) and the cue ball a little off the cue (squirt, from
// side). Plays the strike once without noise up to the first contact and, when that is with
// `object`, turns the ghost ball by the object ball's error: the aim that sends it at
// `aim_point`, to first order. Otherwise the strike's own aim.
double corrected_aim_deg(ShotTrial& trials, const Game& game, const Strike& strike, const Ball& cue,
                         const Ball& object, Vec2 aim_point) {
    World& world = trials.fresh_world();
    if (!world.strike(strike))
        return strike.angle_deg;
    // A direct shot's first contact comes within a few events (motion transitions, spin).
    for (int i = 0; i < 16; ++i) {
        const std::optional<Event> e = world.step();
        if (!e)
            break;
        if (e->kind == EventKind::cushion || e->kind == EventKind::jaw ||
            e->kind == EventKind::pocket)
            break;
        if (e->kind != EventKind::ball_ball)
            continue;
        if (e->ball != 0 || e->other != object.id)
            break;
        const std::vector<Ball> after = world.balls();
        const Ball* hit = ball_in_play(after, object.id);
        if (!hit || length(hit->velocity) == 0)
            break;
        const Vec2 want = normalized(aim_point - object.position);
        const Vec2 got = normalized(hit->velocity);
        const double error = portable::atan2(cross(got, want), dot(got, want));
        const Vec2 turned{want.x * portable::cos(error) - want.y * portable::sin(error),
                          want.x * portable::sin(error) + want.y * portable::cos(error)};
        const Vec2 ghost = object.position - turned * (2 * game.params().ball_radius);
        return aim_degrees(ghost - cue.position);
    }
    return strike.angle_deg;
}

std::vector<PotAim> pot_aims(const Table& table, double R, bool banks) {
    std::vector<PotAim> aims;
    for (int pocket = 1; pocket <= 6; ++pocket) {
        const Vec2 pocket_at = table.pockets[pocket - 1].position;
        aims.push_back({pocket_at, pocket, false});
        if (!banks)
            continue;
        for (const Vec2 mirror : rail_mirrors(table, pocket_at, R))
            if (length(mirror - pocket_at) > 0.2)
                aims.push_back({mirror, pocket, true});
    }
    return aims;
}

std::vector<std::pair<Strike, ShotCall>>
combination_shots(const Game& game, const Ball& cue, const Ball& first, bool (*partner)(int id)) {
    std::vector<std::pair<Strike, ShotCall>> shots;
    const double R = game.params().ball_radius;
    for (const Ball& second : game.balls()) {
        if (!partner(second.id) || second.id == first.id || second.state == MotionState::pocketed)
            continue;
        for (int pocket = 1; pocket <= 6; ++pocket) {
            const Vec2 pocket_at = game.table().pockets[pocket - 1].position;
            const Vec2 to_pocket = normalized(pocket_at - second.position);
            const Vec2 second_ghost = second.position - to_pocket * (2 * R);
            const Vec2 travel = normalized(second_ghost - first.position);
            if (dot(travel, to_pocket) < 0.7)
                continue;
            const Vec2 first_ghost = first.position - travel * (2 * R);
            if (dot(normalized(first_ghost - cue.position), travel) < 0.5 ||
                path_blocked(game.balls(), cue.position, first_ghost, {0, first.id}, R) ||
                path_blocked(game.balls(), first.position, second_ghost, {first.id, second.id},
                             R) ||
                path_blocked(game.balls(), second.position, pocket_at, {0, second.id}, R))
                continue;
            for (const double speed : {2.5, 4.0})
                shots.push_back({{speed, aim_degrees(first_ghost - cue.position), 0, 0},
                                 {{second.id, pocket, false}}});
        }
    }
    return shots;
}

double direction_sigma_deg(Level level) {
    return noise_scale(level) * sigma_aim_deg;
}

int samples_per_candidate(Level level) {
    switch (level) {
    case Level::easy:
        return 1;
    case Level::medium:
        return 3;
    case Level::hard:
        return 6;
    case Level::pro:
        return 16;
    }
    return 1;
}

namespace {

// Snooker's search is the slower: of the spots in the D it searches only the three with the
// best pot in sight and the middle one (for a safety).
std::vector<Vec2> snooker_spots_to_search(const Game& game, std::vector<Vec2> spots,
                                          double sigma_deg) {
    constexpr std::size_t searched = 3;
    if (spots.size() <= searched + 1)
        return spots;
    std::vector<std::pair<double, std::size_t>> ranked;
    for (std::size_t i = 0; i < spots.size(); ++i) {
        Game trial = game;
        if (trial.place_cue_ball(spots[i]))
            ranked.push_back({snooker_best_chance(trial, sigma_deg), i});
    }
    std::ranges::stable_sort(ranked,
                             [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<Vec2> kept;
    for (std::size_t k = 0; k < ranked.size() && k < searched; ++k)
        kept.push_back(spots[ranked[k].second]);
    kept.push_back(spots[spots.size() / 2]);
    return kept;
}

} // namespace

double pot_ease(const Game& game) {
    return game.type() == GameType::snooker ? snooker_next_quality(game) : next_shot_quality(game);
}

ComputerPlayer::ComputerPlayer(Level level, std::uint64_t seed) : level_(level), stream_(seed) {}

ComputerShot ComputerPlayer::search(const Game& game) {
    ComputerShot best;
    best.score = -1e9;
    const Ball* cue = ball_in_play(game.balls(), 0);
    if (!cue)
        return best;
    if (game.is_break()) {
        if (level_ == Level::pro && game.type() != GameType::snooker) {
            best.planned = searched_break(game, *cue, best.score);
            return best;
        }
        best.planned = break_strike(game, *cue);
        best.score = 0;
        return best;
    }
    // Snooker above easy judges its pots by their chance (computer_snooker.cpp).
    if (game.type() == GameType::snooker && level_ != Level::easy)
        return snooker_search(game);
    const double R = game.params().ball_radius;
    const bool snooker = game.type() == GameType::snooker; // here only at easy
    const std::vector<double> speeds =
        level_ == Level::easy ? std::vector<double>{2.5} : std::vector<double>{1.5, 2.5, 4.0};
    const std::vector<double> spins =
        level_ == Level::easy ? std::vector<double>{0.0} : std::vector<double>{-0.3, 0.0, 0.3};

    struct Candidate {
        Strike strike;
        ShotCall call;
        double total = 0;
        int samples = 0;
        double mean() const { return total / samples; }
    };
    std::vector<Candidate> candidates;
    ShotTrial trials(game);
    // Pro's trials of the leaves' next shots, made when a leave is first played out.
    std::optional<ShotTrial> ahead;
    const auto ahead_work = [&] { return ahead ? ahead->work() : 0; };
    const double sigma = direction_sigma_deg(level_);
    auto add = [&](const Ball& object, Vec2 aim_point, int pocket, const std::vector<double>& at) {
        // Skip cuts thinner than about 80 degrees, and shots another ball is in the way of.
        const std::optional<Vec2> line =
            open_pot_line(game.balls(), cue->position, object, aim_point, 0.17, R);
        if (!line)
            return;
        for (const double speed : at)
            for (const double follow : spins) {
                Strike strike{speed, aim_degrees(*line), 0, follow};
                // The players who plan position allow for throw and squirt as well; pro stays
                // above hard by its steadier stroke and its deeper search.
                if (level_ == Level::pro || level_ == Level::hard)
                    strike.angle_deg =
                        corrected_aim_deg(trials, game, strike, *cue, object, aim_point);
                candidates.push_back({strike, {{object.id, pocket, false}}});
            }
    };
    const Table& table = game.table();
    const std::vector<double> bank_speeds{2.5, 4.0};
    // Combinations: the legal ball driven into another, which drops.
    auto add_combinations = [&](const Ball& first) {
        for (const auto& [strike, call] :
             combination_shots(game, *cue, first, [](int id) { return id != 0; }))
            candidates.push_back({strike, call});
    };
    for (const int target : game.legal_targets()) {
        const Ball* object = ball_in_play(game.balls(), target);
        if (!object)
            continue;
        for (const PotAim& aim : pot_aims(table, R, level_ >= Level::hard))
            add(*object, aim.point, aim.pocket, aim.banked ? bank_speeds : speeds);
        if (level_ >= Level::hard)
            add_combinations(*object);
        if (level_ == Level::easy)
            continue;
        // Safeties: soft hits on the ball, full and thinner, called as safety.
        for (const double offset : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
            const Vec2 to_ball = object->position - cue->position;
            const Vec2 aim = object->position + normalized(perpendicular(to_ball)) * (offset * R);
            if (path_blocked(game.balls(), cue->position, object->position, {0, target}, R))
                break;
            for (const double speed : {0.8, 1.6}) {
                ShotCall call;
                call.call.safety = true;
                candidates.push_back({{speed, aim_degrees(aim - cue->position), 0, 0}, call});
            }
        }
    }
    // Each candidate is played under this player's own noise: first once each, then the most
    // promising third again until each has its share of samples (successive halving, one round).
    Random noise = fork_stream(stream_);
    const int shooter = game.shooter();
    auto sample = [&](Candidate& c) {
        const Verdict v = trials.play(noisy(c.strike, game.params(), noise), c.call);
        const Game& trial = trials.after();
        ++simulations_;
        if (snooker) {
            c.total += snooker_points_score(v, shooter);
            ++c.samples;
            return;
        }
        double s = score(v, shooter);
        // Position: a kept table is worth more with a good shot to follow, and a table handed
        // over is worth less the better the opponent's shot (ball in hand: as good as it gets).
        // Pro plays the leave's best next pots out (two shots ahead) and judges the opponent's
        // chance by its spread; the others rate the leave by its best open pot's cut and length.
        if (v.winner == 0 && v.chooser == 0 && level_ == Level::pro && plays_leaves_out_) {
            if (v.next_shooter == shooter)
                s += 60.0 *
                     leave_value(trial, sigma, ahead ? *ahead : ahead.emplace(game), simulations_);
            else
                s -= 60.0 * best_pot_chance(trial, sigma);
        } else if (v.winner == 0 && v.chooser == 0 && level_ != Level::easy) {
            if (v.next_shooter == shooter)
                s += 60.0 * next_shot_quality(trial);
            else
                s -= 60.0 * (v.ball_in_hand != BallInHand::none ? 1.0 : next_shot_quality(trial));
        }
        c.total += s;
        ++c.samples;
    };
    for (Candidate& c : candidates)
        sample(c);
    // On equal means a called pot goes before a safety: a safety that happens to win the rack
    // (the object ball driven on into the money ball) scores like the planned winning pot, but
    // only the pot was aimed at it.
    const auto better = [](const Candidate& x, const Candidate& y) {
        if (x.mean() != y.mean())
            return x.mean() > y.mean();
        return !x.call.call.safety && y.call.call.safety;
    };
    std::ranges::sort(candidates, better);
    const std::size_t keep = std::max<std::size_t>(1, (candidates.size() + 2) / 3);
    if (candidates.size() > keep)
        candidates.resize(keep);
    // A quick search (comparing spots or options) samples as hard does.
    const int samples = plays_leaves_out_ ? samples_per_candidate(level_)
                                          : std::min(samples_per_candidate(level_),
                                                     samples_per_candidate(Level::hard));
    for (Candidate& c : candidates)
        while (c.samples < samples && work_ + trials.work() + ahead_work() < budget_end_)
            sample(c);
    // Out of budget, the last candidates keep their one sample, which may be a lucky one: the
    // choice is made among those sampled in full (the best of the first round, as they were
    // taken in its order), if any.
    if (!candidates.empty() && candidates.front().samples == samples)
        std::erase_if(candidates, [&](const Candidate& c) { return c.samples < samples; });
    if (!candidates.empty()) {
        const Candidate& chosen = *std::ranges::min_element(candidates, better);
        best.score = chosen.mean();
        best.planned = chosen.strike;
        best.call = chosen.call;
    }
    if (best.score == -1e9 && !game.legal_targets().empty()) {
        // Nothing pottable: hit the first legal ball softly.
        const Ball* object = ball_in_play(game.balls(), game.legal_targets().front());
        if (object)
            best.planned = {2.0, aim_degrees(object->position - cue->position), 0, 0};
        best.score = 0;
    }
    work_ += trials.work() + ahead_work();
    return best;
}

Strike ComputerPlayer::with_noise(const Strike& planned, const PhysicsParams& params) {
    return with_stream(stream_, [&](Random& rng) { return noisy(planned, params, rng); });
}

Strike ComputerPlayer::noisy(const Strike& planned, const PhysicsParams& params,
                             Random& rng) const {
    const double k = noise_scale(level_);
    // Box-Muller from the given stream, so that a seed replays the same game.
    auto gaussian = [&] {
        const double u1 = std::max(rng.uniform(), 1e-300), u2 = rng.uniform();
        return std::sqrt(-2 * portable::log(u1)) * portable::cos(2 * std::numbers::pi * u2);
    };
    Strike s = planned;
    s.angle_deg += k * aim_sigma_deg(params) * gaussian();
    s.speed = std::clamp(s.speed + k * sigma_speed * gaussian(), 0.05, max_strike_speed);
    s.side = std::clamp(s.side + k * sigma_tip(params) * gaussian(), -0.5, 0.5);
    s.follow = std::clamp(s.follow + k * sigma_tip(params) * gaussian(), -0.5, 0.5);
    return s;
}

ComputerShot ComputerPlayer::shot(const Game& game) {
    budget_end_ = work_ + decision_budget;
    // The game place_cue_ball was given, now as it left its copy on the chosen spot (every field
    // of its state and score sheet equal): that search's shot, as a search now would find it but
    // for its noise.
    const bool placed = placed_ && placed_->source == reinterpret_cast<std::uintptr_t>(&game) &&
                        placed_->game.type() == game.type() &&
                        placed_->game.state() == game.state() &&
                        placed_->game.score_sheet() == game.score_sheet();
    ComputerShot s = placed ? placed_->shot : search(game);
    placed_.reset();
    s.strike = with_noise(s.planned, game.params());
    return s;
}

Strike ComputerPlayer::break_strike(const Game& game, const Ball& cue) const {
    if (game.type() == GameType::snooker)
        return snooker_break_strike(game);
    // Full power at the apex ball (the one nearest the head of the table), full in the face.
    const Ball* apex = nullptr;
    for (const Ball& b : game.balls()) {
        if (b.id == 0 || b.state == MotionState::pocketed)
            continue;
        if (!apex || b.position.x < apex->position.x)
            apex = &b;
    }
    return {break_speed, apex ? aim_degrees(apex->position - cue.position) : 0, 0, 0};
}

Strike ComputerPlayer::snooker_break_strike(const Game& game) const {
    // The break-off of snooker: thin off the back red of the triangle on the cue ball's side
    // (the line of aim 1.6 R outside its centre), firm, so the cue ball comes back to baulk
    // and the pack barely opens.
    if (!break_off_red(game.balls(), game.params().ball_radius))
        return {2.0, 0, 0, 0};
    return {7.0, break_off_aim_deg(game.balls(), game.params().ball_radius, break_clip), 0, 0};
}

Strike ComputerPlayer::searched_break(const Game& game, const Ball& cue, double& value) {
    // A few paces and lines into the apex ball, each broken several times under noise, worth
    // the referee's view of it and, with the table kept, the best pot it leaves.
    const Strike full = break_strike(game, cue);
    const int shooter = game.shooter();
    const double sigma = direction_sigma_deg(level_);
    const int tries = samples_per_candidate(level_);
    Random noise = fork_stream(stream_);
    ShotTrial trials(game);
    Strike best = full;
    value = -1e18;
    for (const double pace : {9.0, 10.5, 12.0, 13.5})
        for (const double turn_deg : {-0.6, 0.0, 0.6}) {
            const Strike strike{pace, full.angle_deg + turn_deg, 0, 0};
            double total = 0;
            for (int t = 0; t < tries; ++t) {
                const Verdict v = trials.play(noisy(strike, game.params(), noise), {});
                ++simulations_;
                double s = score(v, shooter);
                if (v.winner == 0 && v.chooser == 0 && v.next_shooter == shooter)
                    s += 60.0 * best_pot_chance(trials.after(), sigma);
                total += s;
            }
            if (total / tries > value) {
                value = total / tries;
                best = strike;
            }
        }
    return best;
}

Vec2 ComputerPlayer::place_break(const Game& game) {
    // Spots across the kitchen at the head string; each break tried a few times under noise,
    // scored by the referee (a ball down and the table kept is what a break is for).
    const Table& table = game.table();
    Random noise = fork_stream(stream_);
    // Snooker breaks from the D: spots along the baulk line inside it.
    const bool in_d = game.ball_in_hand() == BallInHand::d;
    const std::vector<Vec2> fallback = in_d ? game.legal_placements(6) : std::vector<Vec2>{};
    Vec2 best_spot = in_d && !fallback.empty() ? fallback.front() : table.head_spot();
    double best = -1e18;
    const int tries = samples_per_candidate(level_);
    for (int k = -3; k <= 3; ++k) {
        const Vec2 spot = in_d
                              ? Vec2{snooker_baulk_x(table),
                                     table.width / 2 + k * snooker_d_radius_on(table) / 3.5}
                              : Vec2{table.head_string_x(), table.width / 2 + k * table.width / 10};
        Game trial = game;
        if (!trial.place_cue_ball(spot))
            continue;
        Ball cue;
        cue.position = spot;
        if (level_ == Level::pro && !in_d) {
            double value = 0;
            searched_break(trial, cue, value);
            if (value > best) {
                best = value;
                best_spot = spot;
            }
            continue;
        }
        const Strike strike = break_strike(trial, cue);
        double total = 0;
        for (int t = 0; t < tries; ++t) {
            Game play = trial;
            const int shooter = play.shooter();
            total += score(play.play(noisy(strike, game.params(), noise), {}), shooter);
            ++simulations_;
        }
        if (total / tries > best) {
            best = total / tries;
            best_spot = spot;
        }
    }
    return best_spot;
}

Vec2 ComputerPlayer::place_cue_ball(const Game& game) {
    budget_end_ = work_ + decision_budget;
    placed_.reset();
    if (game.is_break())
        return place_break(game);
    // Try a spread of legal spots; keep the one whose best shot scores highest.
    std::vector<Vec2> spots = game.legal_placements(level_ == Level::easy ? 4 : 6);
    if (game.type() == GameType::snooker && level_ != Level::easy)
        spots = snooker_spots_to_search(game, std::move(spots), direction_sigma_deg(level_));
    Vec2 best_spot = spots.empty() ? Vec2{} : spots.front();
    double best = -1e18;
    // Pro searches a spot more quickly than a shot (its leaves not played out).
    const bool searched_as_shot = level_ != Level::pro;
    const LeavesNotPlayedOut quick(plays_leaves_out_);
    for (const Vec2 spot : spots) {
        Game trial = game;
        if (!trial.place_cue_ball(spot))
            continue;
        const ComputerShot found = search(trial);
        if (found.score > best) {
            best = found.score;
            best_spot = spot;
            // In full only if no sample was refused for the budget: the work stayed below it.
            if (searched_as_shot && work_ < budget_end_)
                placed_ = Placed{reinterpret_cast<std::uintptr_t>(&game), std::move(trial), found};
            else
                placed_.reset();
        }
    }
    return best_spot;
}

bool ComputerPlayer::concedes(const Game& game) const {
    return snooker_frame_lost(game);
}

Choice ComputerPlayer::choose(const Game& game) {
    budget_end_ = work_ + decision_budget;
    placed_.reset();
    // Each option is judged by the table it leaves: the best shot there for whoever shoots
    // next, good for this player if it shoots, bad if the opponent does. Breaking is worth a
    // little to the breaker.
    const int me = game.chooser();
    Choice best = game.choices().front();
    double best_value = -1e18;
    const LeavesNotPlayedOut quick(plays_leaves_out_);
    for (const Choice option : game.choices()) {
        Game after = game;
        if (!after.choose(option))
            continue;
        const double sign = after.shooter() == me ? 1.0 : -1.0;
        const double value = after.is_break() ? sign * 10.0 : sign * search(after).score;
        if (value > best_value) {
            best_value = value;
            best = option;
        }
    }
    return best;
}

} // namespace termpool
