#include "position_play.hpp"

#include "../support/portable_math.hpp"
#include <algorithm>
#include <cmath>
#include <numbers>

#include "computer_parts.hpp"
#include "shot_lines.hpp"

namespace termpool {
namespace {

// How far off the middle of the mouth a ball may pass and still drop, m, for a ball coming
// straight in; the WPA mouths leave about a radius either side at the corners and more at the
// sides.
constexpr double corner_tolerance = 0.022;
constexpr double side_tolerance = 0.030;
// The cut past which nothing counts as a pot to play for (cos 80 deg).
constexpr double thinnest_cut = 0.17;
// Pots tried from a leave, paces and spins each is tried at.
constexpr std::size_t pots_tried = 3;
constexpr double paces[] = {1.6, 3.0};
constexpr double follows[] = {-0.3, 0.3};

// erf(x) for x >= 0 within 1.5e-7 (Abramowitz and Stegun 7.1.26), on the project's own exp so
// that a decision is the same on every build (libm's erf is not).
double erf_positive(double x) {
    const double t = 1 / (1 + 0.3275911 * x);
    const double poly =
        t * (0.254829592 +
             t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
    return 1 - poly * portable::exp(-x * x);
}

struct PotOption {
    int target = 0;
    int pocket = 0;
    double chance = 0;
    Vec2 line; // cue ball to ghost ball
};

// The legal pots of `game` with nothing in the way, likeliest first.
std::vector<PotOption> pot_options(const Game& game, double sigma_deg) {
    std::vector<PotOption> options;
    const double R = game.params().ball_radius;
    for_each_pot(game, [&](int target, const Ball& cue, const Ball& object, int pocket, Vec2 at) {
        const double chance = pot_chance(game.table(), R, cue.position, object, pocket, sigma_deg);
        if (chance <= 0)
            return;
        const std::optional<Vec2> line =
            open_pot_line(game.balls(), cue.position, object, at, thinnest_cut, R);
        if (line)
            options.push_back({target, pocket, chance, *line});
    });
    std::ranges::stable_sort(
        options, [](const PotOption& a, const PotOption& b) { return a.chance > b.chance; });
    return options;
}

} // namespace

double pot_chance(const Table& table, double R, Vec2 cue, const Ball& object, int pocket,
                  double sigma_deg) {
    const Pocket& p = table.pockets[pocket - 1];
    const Vec2 to_pocket = p.position - object.position;
    const double d2 = length(to_pocket);
    if (d2 <= 0)
        return 1;
    const Vec2 ghost = object.position - to_pocket * (2 * R / d2);
    const Vec2 line = ghost - cue;
    const double d1 = length(line);
    const double cut = d1 > 0 ? dot(line, to_pocket) / (d1 * d2) : 1;
    if (cut < thinnest_cut)
        return 0;
    // The ball comes in along to_pocket; the pocket opens towards -capture_normal.
    const double straight = std::max(0.0, -dot(to_pocket, p.capture_normal) / d2);
    const bool side = pocket == 2 || pocket == 5;
    const double tolerance =
        side ? side_tolerance * straight * straight : corner_tolerance * (0.4 + 0.6 * straight);
    const double sigma = sigma_deg * std::numbers::pi / 180;
    if (sigma <= 0)
        return tolerance > 0 ? 1 : 0;
    // The largest direction error that still drops it.
    const double allowed = tolerance * 2 * R * cut / std::max(d1 * d2, 1e-6);
    return erf_positive(allowed / (sigma * std::numbers::sqrt2));
}

double best_pot_chance(const Game& game, double sigma_deg) {
    if (game.ball_in_hand() != BallInHand::none)
        return 1;
    const std::vector<PotOption> options = pot_options(game, sigma_deg);
    return options.empty() ? 0 : options.front().chance;
}

double leave_value(const Game& game, double sigma_deg, ShotTrial& trials,
                   std::uint64_t& simulations) {
    if (game.ball_in_hand() != BallInHand::none)
        return 1;
    const std::vector<PotOption> options = pot_options(game, sigma_deg);
    const int shooter = game.shooter();
    trials.rebase(game);
    double best = 0;
    for (std::size_t k = 0; k < options.size() && k < pots_tried; ++k) {
        const PotOption& o = options[k];
        // No try can be worth more than the pot's chance: stop when it cannot beat the best.
        if (o.chance <= best)
            break;
        const ShotCall call{{o.target, o.pocket, false}};
        const Ball& cue = *ball_in_play(game.balls(), 0);
        const Ball& object = *ball_in_play(game.balls(), o.target);
        const Vec2 aim_point = game.table().pockets[o.pocket - 1].position;
        for (const double pace : paces)
            for (const double follow : follows) {
                Strike strike{pace, aim_degrees(o.line), 0, follow};
                strike.angle_deg = corrected_aim_deg(trials, game, strike, cue, object, aim_point);
                const Verdict v = trials.play(strike, call);
                ++simulations;
                double after = 0;
                if (v.winner != 0)
                    after = v.winner == shooter ? 1 : -1;
                else if (v.foul == Foul::none && v.next_shooter == shooter && v.chooser == 0)
                    after = best_pot_chance(trials.after(), sigma_deg);
                else
                    continue;
                // A pot is worth its chance, and more with a good shot to follow.
                best = std::max(best, o.chance * (0.5 + 0.5 * after));
            }
    }
    return best;
}

} // namespace termpool
