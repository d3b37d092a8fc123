#pragma once
// Random shots across every model, checked after every event: the stress test in `make test`
// and the longer `make soak` share them. Nothing here uses Catch2, so that shots can be run on
// several threads and their failures counted.

#include "support/random.hpp"
#include "support/text_numbers.hpp"
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <termpool/rack.hpp>
#include <termpool/simulator.hpp>
#include <termpool/table.hpp>
#include <termpool/table_physics.hpp>
#include <thread>
#include <vector>

#include "core/collision.hpp"
#include "physics_helpers.hpp"

namespace termpool::test {

/// One random shot: the setting, the balls at rest and the strike.
struct StressShot {
    std::uint64_t seed = 0;
    Table table;
    PhysicsParams params;
    std::vector<Ball> balls;
    Strike strike;
};

/// What went wrong in a shot, if anything: the first broken promise.
enum class StressFailure {
    none,
    overlap,          ///< two balls overlap by more than 1e-9 m
    off_table,        ///< a ball not pocketed is not on the table (rubber, capture line, outside)
    energy,           ///< the energy rose beyond round-off
    not_finite,       ///< a position or velocity is not a number
    event_limit,      ///< the shot reached World::max_events
    nondeterministic, ///< the same shot twice gave different bits
    stop_event,       ///< a ball came to rest without a stopped event at that instant, or a
                      ///< stopped event came for a ball that did not come to rest
};

/// How many kinds StressFailure has, none included (stop_event is the last).
inline constexpr std::size_t stress_failure_kinds =
    static_cast<std::size_t>(StressFailure::stop_event) + 1;

inline const char* stress_failure_name(StressFailure f) {
    switch (f) {
    case StressFailure::none:
        return "none";
    case StressFailure::overlap:
        return "overlap";
    case StressFailure::off_table:
        return "off-table";
    case StressFailure::energy:
        return "energy";
    case StressFailure::not_finite:
        return "not-finite";
    case StressFailure::event_limit:
        return "event-limit";
    case StressFailure::nondeterministic:
        return "nondeterministic";
    case StressFailure::stop_event:
        return "stop-event";
    }
    return "?";
}

/// How a checked shot went.
struct StressReport {
    std::size_t events = 0;
    StressFailure failure = StressFailure::none;
    std::size_t failed_event = 0;   ///< 1-based event after which the check failed
    std::string detail;             ///< what was measured there
    double worst_energy_rise = 0;   ///< largest rise over one event, J (0 when none)
    double worst_relative_rise = 0; ///< the largest rise over the shot's energy
};

/// The shot for `seed`; one shot in `classic_one_in` uses a classic cloth model. With
/// `snooker`, on the snooker table with snooker balls: snooker racks and up to 22 balls (ids
/// 0..21); the pool shots are the same for a seed as before snooker was added.
inline StressShot make_stress_shot(std::uint64_t seed, std::uint64_t classic_one_in = 5,
                                   bool snooker = false) {
    Random rng(seed * 0x9e3779b97f4a7c15ULL + 1 + (snooker ? 0x5a00cce7ULL : 0));
    StressShot shot;
    shot.seed = seed;
    const TableSize sizes[] = {TableSize::seven_foot, TableSize::eight_foot, TableSize::nine_foot};
    PhysicsParams& p = shot.params;
    if (snooker)
        p = physics_for_table(TableSize::snooker);
    if (rng.below(classic_one_in) == 0) {
        p.friction = random_classic_friction(rng, rng.below(3));
    }
    if (rng.below(2) == 0)
        p.collision = CollisionModel::ideal;
    if (rng.below(2) == 0)
        p.cushion = CushionModel::ideal;
    shot.table = snooker ? make_table(TableSize::snooker, p.ball_radius)
                         : make_table(sizes[rng.below(3)], p.ball_radius);
    const Table& table = shot.table;
    const double R = p.ball_radius;

    if (rng.below(3) == 0) {
        if (snooker)
            shot.balls = make_rack(table, p, RackType::snooker, rng.next());
        else {
            // One draw per statement: the order of a call's arguments is the compiler's choice,
            // and the determinism test keeps the hash of these shots for every compiler.
            const RackType rack = rng.below(2) ? RackType::eight_ball : RackType::nine_ball;
            shot.balls = make_rack(table, p, rack, rng.next());
        }
    } else {
        // Balls anywhere the table holds them, pocket mouths included; some frozen to another
        // ball or to a rail (touching, or 1 nm off), some heavier or lighter.
        const int count = 1 + static_cast<int>(rng.below(snooker ? 22 : 16));
        for (int id = 0; id < count; ++id) {
            for (int attempt = 0; attempt < 100; ++attempt) {
                const double x = rng.uniform(-0.05, table.length + 0.05);
                const double y = rng.uniform(-0.05, table.width + 0.05);
                const double mass = rng.below(4) == 0 ? rng.uniform(0.12, 0.25) : p.ball_mass;
                Ball b = ball_at(id, x, y, mass);
                const double off = rng.below(2) ? 0 : 1e-9;
                switch (rng.below(5)) {
                case 0:
                    b.position.y = rng.below(2) ? R + off : table.width - R - off;
                    break;
                case 1:
                    b.position.x = rng.below(2) ? R + off : table.length - R - off;
                    break;
                case 2:
                case 3:
                    if (!shot.balls.empty()) {
                        const Ball& other = shot.balls[rng.below(shot.balls.size())];
                        const double angle = rng.uniform(0, 2 * std::numbers::pi);
                        b.position = other.position + unit_from_angle(angle) * (2 * R + off);
                    }
                    break;
                default:
                    break;
                }
                if (!on_playing_surface(table, b.position, R))
                    continue;
                const bool clear = std::ranges::none_of(shot.balls, [&](const Ball& o) {
                    return length(o.position - b.position) < 2 * R;
                });
                if (clear) {
                    shot.balls.push_back(b);
                    break;
                }
            }
        }
        if (shot.balls.empty() || shot.balls.front().id != 0)
            shot.balls.insert(shot.balls.begin(),
                              ball_at(0, table.head_string_x(), table.width / 2));
        // The cue ball put in by hand may touch one already there: drop those it overlaps.
        const Vec2 cue = shot.balls.front().position;
        std::erase_if(shot.balls,
                      [&](const Ball& b) { return b.id != 0 && length(b.position - cue) < 2 * R; });
    }
    const double speed = rng.below(5) == 0 ? max_strike_speed : rng.uniform(0, max_strike_speed);
    shot.strike = {speed, rng.uniform(0, 360), rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)};
    // One shot in three with a raised cue (swerve, masse), slowed until it needs no jump.
    if (rng.below(3) == 0) {
        shot.strike.elevation_deg = rng.uniform(0, max_cue_elevation_deg);
        for (int halving = 0; halving < 40 && strike_problem(shot.strike, p); ++halving)
            shot.strike.speed *= 0.5;
    }
    return shot;
}

/// A shot's scenario text for `termpool simulate`, to reproduce a failure.
inline std::string stress_scenario(const StressShot& shot) {
    const auto number = [](double v) { return format_double(v); };
    const PhysicsParams& p = shot.params;
    std::string text = std::string("table ") + table_size_name(shot.table.size) + "\n";
    switch (p.friction.kind) {
    case FrictionKind::physical:
        text += "friction physical\n";
        break;
    case FrictionKind::decay:
        text += "friction decay " + number(p.friction.decay_rate) + "\n";
        break;
    case FrictionKind::constant:
        text += "friction constant " + number(p.friction.deceleration) + "\n";
        break;
    case FrictionKind::combined:
        text += "friction combined " + number(p.friction.decay_rate) + " " +
                number(p.friction.deceleration) + "\n";
        break;
    }
    text += p.collision == CollisionModel::ideal ? "collision ideal\n" : "collision physical\n";
    text += std::string("cushion ") + name_of(cushion_model_names, p.cushion) + "\n";
    if (p.cushion_frequency_ratio != PhysicsParams{}.cushion_frequency_ratio)
        text += "param w_c " + number(p.cushion_frequency_ratio) + "\n";
    for (const Ball& b : shot.balls)
        text += "ball " + std::to_string(b.id) + " " + number(b.position.x) + " " +
                number(b.position.y) + " mass=" + number(b.mass) + "\n";
    text += "strike " + number(shot.strike.speed) + " " + number(shot.strike.angle_deg) + " " +
            number(shot.strike.side) + " " + number(shot.strike.follow) + " " +
            number(shot.strike.elevation_deg) + "\n";
    return text;
}

namespace stress_detail {

inline std::uint64_t mix(std::uint64_t h, double v) {
    return (h ^ std::bit_cast<std::uint64_t>(v)) * 0x100000001b3ULL;
}

// Every bit of every ball, folded into one number.
inline std::uint64_t state_hash(std::uint64_t h, const std::vector<Ball>& balls) {
    for (const Ball& b : balls) {
        for (const double v : {b.position.x, b.position.y, b.velocity.x, b.velocity.y,
                               b.angular_velocity.x, b.angular_velocity.y, b.angular_velocity.z})
            h = mix(h, v);
        h = (h ^ static_cast<std::uint64_t>(b.state) ^
             (static_cast<std::uint64_t>(b.pocket) << 8)) *
            0x100000001b3ULL;
    }
    return h;
}

struct Run {
    StressReport report;
    std::uint64_t hash = 0xcbf29ce484222325ULL;
};

inline Run run_once(const StressShot& shot) {
    Run run;
    StressReport& r = run.report;
    const double R = shot.params.ball_radius;
    World world(shot.table, shot.params, shot.balls);
    world.strike(shot.strike);
    const std::vector<Ball> start = world.balls();
    const double shot_energy = total_energy(start, R);
    // How much energy one event may add: round-off only. A pair that a contact leaves touching
    // is parted at min_separation_speed by turning its relative velocity and paying from its
    // common motion (collision.cpp); only what is at rest there would need energy added, which
    // no contact of 10^5 shots did. What remains is round-off in the sums of energies and
    // impulses: a few ulp of the shot's energy (4 at most), bounded by 1e-14 of it, some 45 ulp.
    const double allowed_rise = 1e-14 * shot_energy;
    double energy = shot_energy;
    // The balls that came to rest at `stop_time` and are owed their stopped event (issue 28:
    // every cloth model reports every stop, a contact's too, at its instant).
    std::vector<Ball> before = start;
    std::vector<int> owed;
    double stop_time = 0;
    const auto fail = [&](StressFailure f, std::string detail) {
        if (r.failure == StressFailure::none) {
            r.failure = f;
            r.failed_event = r.events;
            r.detail = std::move(detail);
        }
    };
    while (const auto e = world.step()) {
        ++r.events;
        const std::vector<Ball> now = world.balls();
        run.hash = state_hash(mix(run.hash, e->time), now);
        if (!owed.empty() && e->time > stop_time)
            fail(StressFailure::stop_event, "ball " + std::to_string(owed.front()) +
                                                " came to rest at " + format_double(stop_time) +
                                                " without a stopped event");
        for (std::size_t i = 0; i < now.size(); ++i) {
            if (before[i].state != MotionState::stationary &&
                before[i].state != MotionState::pocketed &&
                now[i].state == MotionState::stationary) {
                owed.push_back(now[i].id);
                stop_time = e->time;
            }
        }
        before = now;
        if (e->kind == EventKind::stopped) {
            const auto it = std::find(owed.begin(), owed.end(), e->ball);
            if (it == owed.end())
                fail(StressFailure::stop_event, "a stopped event for ball " +
                                                    std::to_string(e->ball) +
                                                    ", which did not come to rest");
            else
                owed.erase(it);
        }
        for (std::size_t i = 0; i < now.size(); ++i) {
            const Ball& a = now[i];
            if (a.state == MotionState::pocketed)
                continue;
            if (!std::isfinite(a.position.x) || !std::isfinite(a.position.y) ||
                !std::isfinite(a.velocity.x) || !std::isfinite(a.velocity.y))
                fail(StressFailure::not_finite, "ball " + std::to_string(a.id));
            if (!on_playing_surface(shot.table, a.position, R))
                fail(StressFailure::off_table,
                     "ball " + std::to_string(a.id) + " at " + format_double(a.position.x) + " " +
                         format_double(a.position.y) + ", rubber depth " +
                         format_double(rubber_depth(shot.table, a.position, R)));
            for (std::size_t j = i + 1; j < now.size(); ++j) {
                const Ball& b = now[j];
                if (b.state == MotionState::pocketed)
                    continue;
                const double overlap = 2 * R - length(a.position - b.position);
                if (overlap > 1e-9)
                    fail(StressFailure::overlap, "balls " + std::to_string(a.id) + " and " +
                                                     std::to_string(b.id) + " by " +
                                                     format_double(overlap) + " m");
            }
        }
        const double e_now = total_energy(now, R);
        const double rise = e_now - energy;
        r.worst_energy_rise = std::max(r.worst_energy_rise, rise);
        if (shot_energy > 0)
            r.worst_relative_rise = std::max(r.worst_relative_rise, rise / shot_energy);
        if (rise > allowed_rise)
            fail(StressFailure::energy,
                 "rose " + format_double(rise) + " J at " + event_kind_name(e->kind) + " " +
                     std::to_string(e->ball) + " " + std::to_string(e->other) + " (allowed " +
                     format_double(allowed_rise) + " J)");
        energy = e_now;
    }
    if (r.events >= World::max_events)
        fail(StressFailure::event_limit, std::to_string(r.events) + " events");
    else if (!owed.empty())
        fail(StressFailure::stop_event, "ball " + std::to_string(owed.front()) +
                                            " came to rest at " + format_double(stop_time) +
                                            " without a stopped event");
    return run;
}

} // namespace stress_detail

/// Runs the shot twice, checking after every event that no two balls overlap by more than
/// 1e-9 m, every ball not pocketed is on the table (on_playing_surface), the energy does not
/// rise beyond round-off, every ball that comes to rest gets its stopped event at that instant
/// (and no other ball one), and both runs pass through the same bits.
inline StressReport check_stress_shot(const StressShot& shot) {
    const stress_detail::Run first = stress_detail::run_once(shot);
    const stress_detail::Run second = stress_detail::run_once(shot);
    StressReport report = first.report;
    if (report.failure == StressFailure::none &&
        (first.hash != second.hash || first.report.events != second.report.events)) {
        report.failure = StressFailure::nondeterministic;
        report.detail = std::to_string(first.report.events) + " and " +
                        std::to_string(second.report.events) + " events";
    }
    return report;
}

/// A shot of more events than this is counted as long: the "a few thousand" at most.
inline constexpr std::size_t long_shot_events = 5000;

/// Counts over many shots.
struct StressTally {
    std::size_t shots = 0, classic_shots = 0, events = 0, most_events = 0;
    std::uint64_t most_events_seed = 0;              ///< the shot that had them
    std::size_t long_shots = 0;                      ///< shots of more than long_shot_events events
    std::vector<std::uint64_t> long_shot_seeds;      ///< the first few of them
    std::size_t failures[stress_failure_kinds] = {}; ///< by StressFailure
    double worst_energy_rise = 0;                    ///< J
    double worst_relative_rise = 0;                  ///< of the shot's energy
    /// The first failures met (seed, kind, detail, scenario), a few at most.
    std::vector<std::string> examples;

    std::size_t failed() const {
        std::size_t n = 0;
        for (std::size_t k = 1; k < stress_failure_kinds; ++k)
            n += failures[k];
        return n;
    }
};

/// Checks the shots of seeds first .. first + count - 1 on `threads` threads (with `snooker`,
/// the snooker table's shots).
inline StressTally run_stress(std::uint64_t first, std::uint64_t count, unsigned threads,
                              std::uint64_t classic_one_in = 5, bool snooker = false) {
    std::vector<StressTally> tallies(std::max(1u, threads));
    std::vector<std::thread> crew;
    for (std::size_t t = 0; t < tallies.size(); ++t) {
        crew.emplace_back([&, t] {
            StressTally& tally = tallies[t];
            for (std::uint64_t k = t; k < count; k += tallies.size()) {
                const StressShot shot = make_stress_shot(first + k, classic_one_in, snooker);
                const StressReport r = check_stress_shot(shot);
                ++tally.shots;
                tally.classic_shots += shot.params.friction.kind != FrictionKind::physical;
                tally.events += r.events;
                if (r.events > long_shot_events) {
                    ++tally.long_shots;
                    if (tally.long_shot_seeds.size() < 5)
                        tally.long_shot_seeds.push_back(first + k);
                }
                if (r.events > tally.most_events) {
                    tally.most_events = r.events;
                    tally.most_events_seed = first + k;
                }
                tally.worst_energy_rise = std::max(tally.worst_energy_rise, r.worst_energy_rise);
                tally.worst_relative_rise =
                    std::max(tally.worst_relative_rise, r.worst_relative_rise);
                if (r.failure == StressFailure::none)
                    continue;
                ++tally.failures[static_cast<std::size_t>(r.failure)];
                if (tally.examples.size() < 5)
                    tally.examples.push_back("seed " + std::to_string(first + k) + ": " +
                                             stress_failure_name(r.failure) + " after event " +
                                             std::to_string(r.failed_event) + ": " + r.detail +
                                             "\n" + stress_scenario(shot));
            }
        });
    }
    for (std::thread& t : crew)
        t.join();
    StressTally all;
    for (const StressTally& t : tallies) {
        all.shots += t.shots;
        all.classic_shots += t.classic_shots;
        all.events += t.events;
        all.long_shots += t.long_shots;
        all.long_shot_seeds.insert(all.long_shot_seeds.end(), t.long_shot_seeds.begin(),
                                   t.long_shot_seeds.end());
        if (t.most_events > all.most_events) {
            all.most_events = t.most_events;
            all.most_events_seed = t.most_events_seed;
        }
        all.worst_energy_rise = std::max(all.worst_energy_rise, t.worst_energy_rise);
        all.worst_relative_rise = std::max(all.worst_relative_rise, t.worst_relative_rise);
        for (std::size_t k = 0; k < stress_failure_kinds; ++k)
            all.failures[k] += t.failures[k];
        for (const std::string& e : t.examples)
            if (all.examples.size() < 5)
                all.examples.push_back(e);
    }
    return all;
}

} // namespace termpool::test
