// Settling a kick's aim: a coarse scan of aims around the mirror aim, each played by the
// simulator up to the cue ball's first ball, then a bisection towards the fullest hit.

#include "tui/kick_aim.hpp"

#include <cmath>
#include <cstdlib>

#include "tui/aim.hpp"

namespace termpool::tui {
namespace {

// Events before the cue ball's first ball on a table at rest: a slide, a roll, one rail and
// another slide and roll. Far more than it needs; the bound keeps a broken table from stalling.
constexpr int max_events = 64;

// One aim played: whether the cue ball meets `target` first after exactly one cushion, and how
// full: the sine of the cut, signed (0 full, +-1 the thinnest hit on either side).
struct Trial {
    bool meets = false;
    double offset = 0;
};

std::optional<Ball> cue_of(const World& world) {
    for (const Ball& b : world.balls())
        if (b.id == 0)
            return b;
    return std::nullopt;
}

Trial play(const World& at_rest, const Strike& strike, int target) {
    World world = at_rest;
    if (!world.strike(strike))
        return {};
    std::optional<Ball> cue = cue_of(world);
    int rails = 0;
    for (int n = 0; n < max_events && cue; ++n) {
        const std::optional<Event> e = world.step();
        if (!e)
            return {};
        switch (e->kind) {
        case EventKind::sliding:
        case EventKind::rolling:
            // Only the cue ball moves before its first ball: its heading from here on is the
            // one it meets the ball with (straight once rolling, a little curved while sliding).
            cue = cue_of(world);
            continue;
        case EventKind::cushion:
            if (++rails > 1)
                return {};
            cue = cue_of(world);
            continue;
        case EventKind::ball_ball: {
            // The cue ball is id 0, the lower id of any pair it is in.
            if (e->ball != 0 || e->other != target || rails != 1)
                return {};
            const std::optional<Ball> at_contact = cue_of(world);
            for (const Ball& b : world.balls())
                if (b.id == target && at_contact)
                    return {true, cross(normalized(cue->velocity),
                                        normalized(b.position - at_contact->position))};
            return {};
        }
        case EventKind::jaw:
        case EventKind::pocket:
        case EventKind::spinning:
        case EventKind::stopped:
        case EventKind::off_table:
            return {};
        }
    }
    return {};
}

// The trial at `delta` degrees from the mirror aim, and the aim it was played at.
struct Aimed {
    double aim = 0;
    Trial trial;
};

} // namespace

std::optional<double> refine_kick(const Table& table, const PhysicsParams& params,
                                  const std::vector<Ball>& balls, const Strike& strike,
                                  int target) {
    if (strike_problem(strike, params))
        return std::nullopt;
    const World at_rest(table, params, balls);
    const auto at = [&](double delta) {
        Strike s = strike;
        s.angle_deg = turn(strike.angle_deg, delta);
        return Aimed{s.angle_deg, play(at_rest, s, target)};
    };

    // The coarse scan: the aims that meet the ball, and of them the fullest (nearest the
    // mirror aim when two are as full).
    const int steps = static_cast<int>(std::lround(kick_search_deg / kick_scan_step_deg));
    std::vector<Aimed> scan;
    int best = -1;
    for (int k = -steps; k <= steps; ++k) {
        scan.push_back(at(k * kick_scan_step_deg));
        const Trial& t = scan.back().trial;
        if (!t.meets)
            continue;
        const auto i = static_cast<int>(scan.size()) - 1;
        const Trial* b = best >= 0 ? &scan[static_cast<std::size_t>(best)].trial : nullptr;
        if (!b || std::fabs(t.offset) < std::fabs(b->offset) ||
            (std::fabs(t.offset) == std::fabs(b->offset) && std::abs(k) < std::abs(best - steps)))
            best = i;
    }
    if (best < 0)
        return std::nullopt;

    // Towards a full hit from the fullest aim found: on one side of it the hit turns fuller
    // until the cut changes side, or another ball or a miss takes over. Bisect each side on
    // which the next aim scanned is not a hit as thin or thinner on the same side.
    const Aimed found = scan[static_cast<std::size_t>(best)];
    const double side = found.trial.offset < 0 ? -1 : 1;
    const auto same_side = [&](const Trial& t) { return t.meets && t.offset * side >= 0; };
    Aimed settled = found;
    for (const int neighbour : {best - 1, best + 1}) {
        if (found.trial.offset == 0)
            break;
        if (neighbour < 0 || neighbour >= static_cast<int>(scan.size()) ||
            same_side(scan[static_cast<std::size_t>(neighbour)].trial))
            continue;
        double inside = (best - steps) * kick_scan_step_deg;
        double outside = (neighbour - steps) * kick_scan_step_deg;
        Aimed last = found;
        while (std::fabs(outside - inside) > kick_resolution_deg) {
            const double middle = (inside + outside) / 2;
            const Aimed a = at(middle);
            if (same_side(a.trial)) {
                inside = middle;
                last = a;
            } else {
                outside = middle;
            }
        }
        if (std::fabs(last.trial.offset) < std::fabs(settled.trial.offset))
            settled = last;
    }
    return settled.aim;
}

} // namespace termpool::tui
