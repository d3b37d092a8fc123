// The scripted safe player: an easy pot or a safety, each found by simulating a few strokes
// on a copy of the frame and asking the referee what they would mean.
#include "../support/portable_math.hpp"
#include "../support/random.hpp"
#include <algorithm>
#include <cmath>
#include <numbers>
#include <termpool/break_off.hpp>
#include <termpool/game_registry.hpp>
#include <termpool/safe_player.hpp>
#include <termpool/snooker_layout.hpp>

#include "shot_lines.hpp"
#include "snooker_leave.hpp"

namespace termpool {
namespace {

// Execution noise as the hard computer's: the direction (degrees) and the pace (m/s).
constexpr double sigma_aim_deg = 0.125;
constexpr double sigma_speed = 0.075;

// `planned` as its stroke plays it: Box-Muller from the given stream, so that a seed replays
// the same frame.
Strike with_noise(const Strike& planned, Random& rng) {
    const double u1 = std::max(rng.uniform(), 1e-300), u2 = rng.uniform();
    const double g = std::sqrt(-2 * portable::log(u1));
    Strike s = planned;
    s.angle_deg += sigma_aim_deg * g * portable::cos(2 * std::numbers::pi * u2);
    s.speed = std::clamp(s.speed + sigma_speed * g * portable::sin(2 * std::numbers::pi * u2), 0.05,
                         max_strike_speed);
    return s;
}

// A pot it may try: the ball into the pocket by the ghost-ball aim, and how often of four
// noisy strokes it dropped with the table kept.
struct Pot {
    Strike strike;
    ShotCall call;
    int made = 0;
    int value = 0;
    double distance = 0;
};

// The call of a shot at `ball`: with a nomination owed the ball is named (a colour, or a free
// ball), else a pot names its pocket and a safety says so.
ShotCall call_for(const Game& game, int ball, int pocket) {
    ShotCall call;
    if (pocket != 0 || game.nomination_owed()) {
        call.call.ball = ball;
        call.call.pocket = pocket;
    } else {
        call.call.safety = true;
    }
    return call;
}

// The balls it plays at: those on (a colour after a red it nominates).
std::vector<int> targets(const Game& game) {
    return game.balls_on();
}

// How good a safety left the table, from the player who played it: a foul or the frame lost
// is worst; a pot by chance keeps the table; else the opponent's easiest pot counts against
// it, and a snooker, the cue ball far from the balls on, on a cushion, or in baulk for it.
double safety_value(const Verdict& v, const Game& after, int me) {
    if (v.winner != 0)
        return v.winner == me ? 1e6 : -1e6;
    if (v.foul != Foul::none)
        return -1000.0 - 10.0 * v.penalty;
    if (v.next_shooter == me)
        return 20.0 + 10.0 * v.points;
    return with_leave_worth(-100.0 * pot_ease(after), after, false);
}

// The pots from the cue ball's place: every ball on into every pocket with clear lines, a cut
// of at most about 40 degrees and not too far, each tried four times under the noise.
std::vector<Pot> pots(const Game& game, Random& noise) {
    std::vector<Pot> found;
    const Ball* cue = ball_in_play(game.balls(), 0);
    if (!cue)
        return found;
    const double R = game.params().ball_radius;
    const int me = game.shooter();
    for (const int id : targets(game)) {
        const Ball* object = ball_in_play(game.balls(), id);
        if (!object)
            continue;
        for (int pocket = 1; pocket <= 6; ++pocket) {
            const Vec2 at = game.table().pockets[pocket - 1].position;
            const std::optional<Vec2> line =
                open_pot_line(game.balls(), cue->position, *object, at, 0.77, R);
            if (!line)
                continue;
            const double travel = length(*line) + length(at - object->position);
            if (travel > 2.6)
                continue;
            Pot pot{{std::clamp(1.0 + 0.5 * travel, 1.2, 2.6), aim_degrees(*line), 0, 0},
                    call_for(game, id, pocket),
                    0,
                    snooker_value(id),
                    travel};
            for (int k = 0; k < 4; ++k) {
                Game trial = game;
                const Verdict v = trial.play(with_noise(pot.strike, noise), pot.call);
                if (v.foul == Foul::none && v.next_shooter == me &&
                    std::ranges::count(v.pocketed, id))
                    ++pot.made;
            }
            found.push_back(pot);
        }
    }
    return found;
}

// The easiest pot: the most often made, then the most valuable, then the shortest.
const Pot* easiest(const std::vector<Pot>& found) {
    const Pot* best = nullptr;
    for (const Pot& p : found)
        if (!best || p.made > best->made ||
            (p.made == best->made &&
             (p.value > best->value || (p.value == best->value && p.distance < best->distance))))
            best = &p;
    return best;
}

// The safeties: each ball on in line hit from full to thin at four paces; a ball on that the
// cue ball cannot see directly, off each cushion (the escape from a snooker).
std::vector<std::pair<Strike, ShotCall>> safeties(const Game& game) {
    std::vector<std::pair<Strike, ShotCall>> found;
    const Ball* cue = ball_in_play(game.balls(), 0);
    if (!cue)
        return found;
    const double R = game.params().ball_radius;
    const Table& t = game.table();
    for (const int id : targets(game)) {
        const Ball* object = ball_in_play(game.balls(), id);
        if (!object)
            continue;
        const ShotCall call = call_for(game, id, 0);
        const Vec2 to_ball = object->position - cue->position;
        if (!path_blocked(game.balls(), cue->position, object->position, {0, id}, R)) {
            for (const double offset : {-1.8, -1.3, -0.7, 0.0, 0.7, 1.3, 1.8}) {
                const Vec2 aim =
                    object->position + normalized(perpendicular(to_ball)) * (offset * R);
                for (const double speed : {0.8, 1.4, 2.2, 3.2})
                    found.push_back({{speed, aim_degrees(aim - cue->position), 0, 0}, call});
            }
            continue;
        }
        for (const Vec2 mirror : rail_mirrors(t, object->position, R))
            for (const double speed : {1.5, 2.5, 3.5})
                found.push_back({{speed, aim_degrees(mirror - cue->position), 0, 0}, call});
    }
    return found;
}

// The break-off: firm and thin off the end red of the pack on the cue ball's side, so the cue
// ball comes off the side and top cushions back to baulk.
Strike break_off(const Game& game) {
    if (!break_off_red(game.balls(), game.params().ball_radius))
        return {2.0, 0, 0, 0};
    return {7.0, break_off_aim_deg(game.balls(), game.params().ball_radius, break_clip), 0, 0};
}

} // namespace

SafePlayer::SafePlayer(std::uint64_t seed) : stream_(seed) {}

ComputerShot SafePlayer::shot(const Game& game) {
    ComputerShot chosen;
    if (game.is_break()) {
        chosen.planned = break_off(game);
        chosen.strike =
            with_stream(stream_, [&](Random& rng) { return with_noise(chosen.planned, rng); });
        return chosen;
    }
    Random noise = fork_stream(stream_);
    const std::vector<Pot> found = pots(game, noise);
    if (const Pot* pot = easiest(found); pot && pot->made >= easy_of_four) {
        chosen.planned = pot->strike;
        chosen.call = pot->call;
        chosen.score = pot->made;
        chosen.strike =
            with_stream(stream_, [&](Random& rng) { return with_noise(chosen.planned, rng); });
        return chosen;
    }
    // The safeties, judged without noise first; the best few again under it.
    const int me = game.shooter();
    struct Judged {
        Strike strike;
        ShotCall call;
        double value = 0;
    };
    std::vector<Judged> judged;
    for (const auto& [strike, call] : safeties(game)) {
        Game trial = game;
        const Verdict v = trial.play(strike, call);
        judged.push_back({strike, call, safety_value(v, trial, me)});
    }
    if (judged.empty()) {
        // No ball on in sight at all: hit the first ball on firmly (a foul at worst).
        const Ball* cue = ball_in_play(game.balls(), 0);
        const std::vector<int> on = targets(game);
        const Ball* object = on.empty() ? nullptr : ball_in_play(game.balls(), on.front());
        if (cue && object)
            chosen.planned = {2.0, aim_degrees(object->position - cue->position), 0, 0};
        chosen.call = call_for(game, object ? object->id : 0, 0);
        chosen.strike =
            with_stream(stream_, [&](Random& rng) { return with_noise(chosen.planned, rng); });
        return chosen;
    }
    std::ranges::stable_sort(judged,
                             [](const Judged& a, const Judged& b) { return a.value > b.value; });
    if (judged.size() > 8)
        judged.resize(8);
    for (Judged& j : judged) {
        double total = j.value;
        for (int k = 0; k < 3; ++k) {
            Game trial = game;
            const Verdict v = trial.play(with_noise(j.strike, noise), j.call);
            total += safety_value(v, trial, me);
        }
        j.value = total / 4;
    }
    const Judged& best = *std::ranges::max_element(
        judged, [](const Judged& a, const Judged& b) { return a.value < b.value; });
    chosen.planned = best.strike;
    chosen.call = best.call;
    chosen.score = best.value;
    chosen.strike =
        with_stream(stream_, [&](Random& rng) { return with_noise(chosen.planned, rng); });
    return chosen;
}

Vec2 SafePlayer::place_cue_ball(const Game& game) {
    const Table& t = game.table();
    const std::vector<Vec2> spots = game.legal_placements(6);
    if (game.is_break()) {
        // Between the yellow and the brown on the baulk line.
        const Vec2 spot = (snooker_spot(t, snooker_yellow) + snooker_spot(t, snooker_brown)) * 0.5;
        if (game.legal_placement(spot) || spots.empty())
            return spot;
        return spots.front();
    }
    // Where an easy pot is most often made; with none, the spot nearest the brown's (the
    // middle of the D, from where the cue ball is rolled back to baulk).
    Vec2 best_spot = snooker_d_centre(t);
    int best_made = -1;
    double best_to_centre = 1e9;
    Random noise = fork_stream(stream_);
    for (const Vec2 spot : spots) {
        Game trial = game;
        if (!trial.place_cue_ball(spot))
            continue;
        const std::vector<Pot> found = pots(trial, noise);
        const Pot* pot = easiest(found);
        const int made = pot && pot->made >= easy_of_four ? pot->made : 0;
        const double to_centre = length(spot - snooker_d_centre(t));
        if (made > best_made || (made == best_made && to_centre < best_to_centre)) {
            best_made = made;
            best_to_centre = to_centre;
            best_spot = spot;
        }
    }
    return best_spot;
}

Choice SafePlayer::choose(const Game& game) const {
    const int me = game.chooser();
    Choice best = game.choices().front();
    double best_value = -1e18;
    for (const Choice option : game.choices()) {
        Game after = game;
        if (option == Choice::concede || !after.choose(option))
            continue;
        const double ease = pot_ease(after);
        const double value = after.shooter() == me ? ease : -ease;
        if (value > best_value) {
            best_value = value;
            best = option;
        }
    }
    return best;
}

bool SafePlayer::concedes(const Game& game) const {
    return snooker_frame_lost(game);
}

} // namespace termpool
