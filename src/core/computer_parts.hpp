#pragma once
// The parts of the computer's search that its pool and its snooker searches share: the spread
// of its stroke, its samples, and the aim that allows for throw and squirt.

#include <termpool/level.hpp>
#include <termpool/rules.hpp>
#include <utility>
#include <vector>

#include "shot_lines.hpp"
#include "shot_trial.hpp"

namespace termpool {

// The whole spread (one standard deviation) of the cue ball's direction under the execution
// noise of `level`, degrees: aim and squirt together.
double direction_sigma_deg(Level level);

// Noisy samples of each promising candidate at `level` (1, 3, 6, 16).
int samples_per_candidate(Level level);

// The ghost-ball aim of `strike` at `object`, turned by the object ball's error (throw, and the
// squirt of any side) so that it leaves towards `aim_point`, to first order; the strike's own
// aim when its first contact is not with `object`.
// `trials` are of `game`: the strike is played on a fresh copy of its world.
double corrected_aim_deg(ShotTrial& trials, const Game& game, const Strike& strike, const Ball& cue,
                         const Ball& object, Vec2 aim_point);

// Calls `visit(target, cue, object, pocket, at)` for every legal ball on the table in `game`
// and every pocket (`at`: its position), the cue ball on the table; nothing without one.
template <class Visit> void for_each_pot(const Game& game, Visit visit) {
    const Ball* cue = ball_in_play(game.balls(), 0);
    if (!cue)
        return;
    for (const int target : game.legal_targets()) {
        const Ball* object = ball_in_play(game.balls(), target);
        if (!object)
            continue;
        for (int pocket = 1; pocket <= 6; ++pocket)
            visit(target, *cue, *object, pocket, game.table().pockets[pocket - 1].position);
    }
}

// The best of `rate(target, cue, object, pocket, best)` over the balls on in `game` and the
// pockets, counting only the pots whose ghost-ball line from the cue ball and whose line on to
// the pocket are clear; 0 at worst, and with no cue ball on the table. `rate` returns 0 for a
// pot not worth looking at, and may return 0 for one it can tell at once is worth no more than
// `best`, the best so far (the lines are looked at only for a better one).
template <class Rate> double best_clear_pot(const Game& game, Rate rate) {
    const double R = game.params().ball_radius;
    double best = 0;
    for_each_pot(game, [&](int target, const Ball& cue, const Ball& object, int pocket, Vec2 at) {
        const double value = rate(target, cue, object, pocket, best);
        if (!(value > best))
            return; // the lines are looked at only for a better pot
        const Vec2 ghost = object.position - normalized(at - object.position) * (2 * R);
        if (!path_blocked(game.balls(), cue.position, ghost, {0, target}, R) &&
            !path_blocked(game.balls(), object.position, at, {0, target}, R))
            best = value;
    });
    return best;
}

// An aim of a pot: the point the object ball is sent at, and the pocket it is meant for.
struct PotAim {
    Vec2 point;
    int pocket = 0;
    bool banked = false; // off one rail: `point` is the pocket's mirror image in it
};

// The aims of a pot into each pocket in turn: straight at it, and with `banks` off each rail
// as well (at the pocket's image in the rail, moved in by R because the ball's centre turns R
// from the cushion), where that image is not the pocket itself.
std::vector<PotAim> pot_aims(const Table& table, double R, bool banks);

// The combinations of `first` driven into another ball on the table that `partner` accepts
// (by its id), which drops: for each such ball and pocket where the cuts on both balls are
// fairly full and the lines clear (so that the search stays within its time), the aim at
// `first`'s ghost ball at two paces, called as that ball into that pocket.
std::vector<std::pair<Strike, ShotCall>>
combination_shots(const Game& game, const Ball& cue, const Ball& first, bool (*partner)(int id));

} // namespace termpool
