// The computer's snooker search. A pot is judged by its chance under the player's own stroke:
// the window of aims that pot the ball (found by bisection without noise) against the spread
// of its cue ball's direction, so that a long or thin pot it makes one time in four is played
// as that, not as the lucky sample of a few. Its worth is the chance times the table kept
// (points and position) plus the misses times the table they hand over. Safeties and
// combinations are sampled under the noise, as in pool. Tables are valued by
// snooker_leave.cpp.
#include "../support/portable_math.hpp"
#include "../support/random.hpp"
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <termpool/computer.hpp>
#include <termpool/snooker_layout.hpp>

#include "computer_parts.hpp"
#include "shot_lines.hpp"
#include "snooker_leave.hpp"

namespace termpool {
namespace {

// What a missed pot costs besides the table it leaves, in the search's units (12 to a point).
// The two misses simulated are near ones, at the window's edges; a wider miss, or an opponent
// who plays better than this player's own stroke, leaves more. Without it the computer goes
// for pots it makes one time in four whenever the near misses leave nothing.
constexpr double miss_cost = 60;

// The sampled shots (safeties, combinations) played under the noise, at most.
constexpr std::size_t sampled_at_most = 48;

// The sampled shots played afresh to judge them.
constexpr std::size_t finalists = 4;

// The widest half-window looked for, degrees: a pot open wider than this is as good as sure.
constexpr double widest_window_deg = 1.28;

// The aims that pot `target` for the shooter, legally and with the table kept, as offsets
// from `stroke`'s aim: how far they reach on the side of `sign` (+1 or -1), in degrees; 0
// when the aim itself does not pot it. Doubling steps out to the first miss, then three
// halvings of the last step.
double window_edge(ShotTrial& trials, const Game& game, Strike stroke, const ShotCall& call,
                   int target, int sign, std::uint64_t& simulations) {
    const int shooter = game.shooter();
    const double centre = stroke.angle_deg;
    auto pots = [&](double offset) {
        stroke.angle_deg = centre + sign * offset;
        const Verdict v = trials.play(stroke, call);
        ++simulations;
        return v.foul == Foul::none && v.next_shooter == shooter &&
               std::ranges::count(v.pocketed, target) > 0;
    };
    double good = 0, bad = -1;
    for (double step = 0.02; step <= widest_window_deg; step *= 2) {
        if (!pots(step)) {
            bad = step;
            break;
        }
        good = step;
    }
    if (bad < 0)
        return good;
    for (int i = 0; i < 3; ++i) {
        const double mid = (good + bad) / 2;
        (pots(mid) ? good : bad) = mid;
    }
    return (good + bad) / 2;
}

} // namespace

ComputerShot ComputerPlayer::snooker_search(const Game& game) {
    ComputerShot best;
    best.score = -1e9;
    const Ball* cue = ball_in_play(game.balls(), 0);
    if (!cue)
        return best;
    const double R = game.params().ball_radius;
    const int shooter = game.shooter();
    const Table& table = game.table();
    const double sigma = direction_sigma_deg(level_);
    // Hard and pro add banks and combinations. Every level here aims for throw and squirt: the
    // window of a pot is measured around an aim that pots it without noise.
    const bool plays_banks = level_ >= Level::hard;
    const std::vector<double> speeds{1.0, 1.5, 2.5, 4.0};
    const std::vector<double> bank_speeds{2.5, 4.0};
    const std::vector<double> spins{-0.45, -0.2, 0.0, 0.2, 0.45};
    const std::size_t windows_per_pot = level_ == Level::pro ? 4 : 3;
    ShotTrial trials(game);

    auto consider = [&](const Strike& strike, const ShotCall& call, double value) {
        if (value > best.score) {
            best.score = value;
            best.planned = strike;
            best.call = call;
        }
    };
    auto outcome = [&](const Strike& strike, const ShotCall& call) {
        const Verdict v = trials.play(strike, call);
        const Game& trial = trials.after();
        ++simulations_;
        return snooker_shot_value(v, shooter, trial, sigma);
    };

    // Pots, by their chance: each ball and pocket (and, for hard and pro, each one-rail bank)
    // at each pace and spin, aimed by the ghost ball (hard and pro: corrected for throw and
    // squirt). The strokes that pot it without noise are ranked by the table they leave; the
    // best few have their window of aims measured, are aimed at its middle, and are worth
    // their chance times that table plus the misses times the tables two near misses leave.
    auto add_pot = [&](const Ball& object, Vec2 aim_point, int pocket,
                       const std::vector<double>& paces) {
        const std::optional<Vec2> line =
            open_pot_line(game.balls(), cue->position, object, aim_point, 0.17, R);
        if (!line)
            return;
        const ShotCall call{{object.id, pocket, false}};
        // Every pace and spin without noise first: those that pot it with the table kept, by
        // the table they leave; the best few then have their window measured.
        struct Stroke {
            Strike strike;
            double made = 0;
        };
        std::vector<Stroke> strokes;
        for (const double speed : paces)
            for (const double follow : spins) {
                Strike strike{speed, aim_degrees(*line), 0, follow};
                strike.angle_deg = corrected_aim_deg(trials, game, strike, *cue, object, aim_point);
                const Verdict v = trials.play(strike, call);
                const Game& trial = trials.after();
                ++simulations_;
                if (v.foul == Foul::none && v.next_shooter == shooter &&
                    std::ranges::count(v.pocketed, object.id) > 0)
                    strokes.push_back({strike, snooker_shot_value(v, shooter, trial, sigma)});
            }
        std::ranges::stable_sort(strokes,
                                 [](const Stroke& x, const Stroke& y) { return x.made > y.made; });
        if (strokes.size() > windows_per_pot)
            strokes.resize(windows_per_pot);
        for (Stroke& stroke : strokes) {
            const double above =
                window_edge(trials, game, stroke.strike, call, object.id, 1, simulations_);
            const double below =
                window_edge(trials, game, stroke.strike, call, object.id, -1, simulations_);
            const double middle = (above - below) / 2, half = (above + below) / 2;
            const double chance = chance_within(half, sigma);
            Strike strike = stroke.strike;
            double made = stroke.made;
            if (middle != 0) {
                strike.angle_deg += middle;
                const Verdict v = trials.play(strike, call);
                const Game& trial = trials.after();
                ++simulations_;
                if (v.foul != Foul::none || v.next_shooter != shooter ||
                    std::ranges::count(v.pocketed, object.id) == 0) {
                    strike = stroke.strike; // the middle of a broken window: keep the aim
                } else {
                    made = snooker_shot_value(v, shooter, trial, sigma);
                }
            }
            // A miss goes past the window's edge by about the spread.
            const double past = half + 0.8 * sigma;
            Strike wide = strike, thin = strike;
            wide.angle_deg += past;
            thin.angle_deg -= past;
            const double missed = (outcome(wide, call) + outcome(thin, call)) / 2 - miss_cost;
            consider(strike, call, chance * made + (1 - chance) * missed);
        }
    };

    // The rest is sampled under the noise: safeties (the ball on hit full to thin at four
    // paces, or off one cushion where the line to it is blocked) and combinations.
    struct Sampled {
        Strike strike;
        ShotCall call;
        double plain = 0;  // its worth played once without noise, then its mean under it
        bool pots = false; // a safety that pots a ball on without noise
    };
    std::vector<Sampled> sampled;
    auto add_safeties = [&](const Ball& object) {
        // Called as a safety, also on a colour: the referee takes the colour hit first as the
        // one nominated, and the statistics count no pot missed.
        ShotCall call;
        call.call.safety = true;
        const Vec2 to_ball = object.position - cue->position;
        if (!path_blocked(game.balls(), cue->position, object.position, {0, object.id}, R)) {
            for (const double offset : {-1.8, -1.4, -0.9, -0.4, 0.0, 0.4, 0.9, 1.4, 1.8}) {
                const Vec2 aim =
                    object.position + normalized(perpendicular(to_ball)) * (offset * R);
                for (const double speed : {0.8, 1.6, 2.6, 3.6})
                    sampled.push_back({{speed, aim_degrees(aim - cue->position), 0, 0}, call});
            }
            return;
        }
        for (const Vec2 mirror : rail_mirrors(table, object.position, R))
            for (const double speed : {1.6, 2.6, 3.6})
                sampled.push_back({{speed, aim_degrees(mirror - cue->position), 0, 0}, call});
    };
    // A combination is a red into a red: any other pots a ball not on, or hits one first.
    auto add_combinations = [&](const Ball& first) {
        if (game.snooker().ball_on != BallOn::red || game.snooker().free_ball ||
            !is_snooker_red(first.id))
            return;
        for (const auto& [strike, call] : combination_shots(game, *cue, first, is_snooker_red))
            sampled.push_back({strike, call});
    };

    for (const int target : game.legal_targets()) {
        const Ball* object = ball_in_play(game.balls(), target);
        if (!object)
            continue;
        for (const PotAim& aim : pot_aims(table, R, plays_banks))
            add_pot(*object, aim.point, aim.pocket, aim.banked ? bank_speeds : speeds);
        if (plays_banks)
            add_combinations(*object);
        add_safeties(*object);
    }

    // The sampled ones are ranked by one play without noise; a safety that pots a ball on
    // there is a pot, which the pot search judges by its chance: dropped. The best third (at
    // most sampled_at_most) are then played under the noise, worth the mean of those plays.
    for (Sampled& c : sampled) {
        const Verdict v = trials.play(c.strike, c.call);
        const Game& trial = trials.after();
        ++simulations_;
        c.plain = snooker_shot_value(v, shooter, trial, sigma);
        c.pots = c.call.call.safety && v.foul == Foul::none && v.next_shooter == shooter;
    }
    std::erase_if(sampled, [](const Sampled& c) { return c.pots; });
    std::ranges::stable_sort(sampled,
                             [](const Sampled& x, const Sampled& y) { return x.plain > y.plain; });
    const std::size_t keep = std::min(sampled_at_most, (sampled.size() + 2) / 3);
    if (sampled.size() > keep)
        sampled.resize(keep);
    Random noise = fork_stream(stream_);
    auto mean_of = [&](const Sampled& c, int plays) {
        double total = 0;
        for (int k = 0; k < plays; ++k) {
            const Verdict v = trials.play(noisy(c.strike, game.params(), noise), c.call);
            const Game& trial = trials.after();
            ++simulations_;
            total += snooker_shot_value(v, shooter, trial, sigma);
        }
        return total / plays;
    };
    for (Sampled& c : sampled)
        c.plain = mean_of(c, samples_per_candidate(level_));
    // The best of many noisy means is flattered by its luck: the few best are played afresh,
    // twice as often, and that mean is their worth.
    std::ranges::stable_sort(sampled,
                             [](const Sampled& x, const Sampled& y) { return x.plain > y.plain; });
    if (sampled.size() > finalists)
        sampled.resize(finalists);
    for (const Sampled& c : sampled)
        consider(c.strike, c.call, mean_of(c, 2 * samples_per_candidate(level_)));

    if (best.score == -1e9 && !game.legal_targets().empty()) {
        // Nothing in sight: hit the first legal ball softly.
        if (const Ball* object = ball_in_play(game.balls(), game.legal_targets().front()))
            best.planned = {2.0, aim_degrees(object->position - cue->position), 0, 0};
        best.score = 0;
    }
    return best;
}

} // namespace termpool
