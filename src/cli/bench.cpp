// `termpool bench`: times seeded breaks and random post-break shots on one core.

#include "support/portable_math.hpp"
#include "support/random.hpp"
#include "support/state_digest.hpp"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <optional>
#include <string>
#include <termpool/game_registry.hpp>
#include <termpool/rack.hpp>
#include <termpool/simulator.hpp>
#include <termpool/snooker_layout.hpp>
#include <termpool/table.hpp>
#include <termpool/table_physics.hpp>

#include "cli/commands.hpp"
#include "cli/cpu_clock.hpp"
#include "cli/numbers.hpp"

namespace termpool::cli {
namespace {

constexpr const char* usage = "usage: termpool bench [--breaks N] [--shots N] [--seed S]\n"
                              "                      [--balls LIST] [--ball-runs N]\n"
                              "       termpool bench --render\n"
                              "  --breaks N  seeded 8-ball breaks to time, and as many snooker\n"
                              "              breaks (default 1000, N >= 1)\n"
                              "  --shots N   random shots on the break layouts of each (default\n"
                              "              10000)\n"
                              "  --seed S    seed of the break angles and the shots (default 1)\n"
                              "  --balls LIST  ball counts of the cost-per-event rows, up to 16,\n"
                              "              each 2..1024 (default 16,32,64,128)\n"
                              "  --ball-runs N  breaks per ball count (default 100, at most\n"
                              "              100000; 0: no rows)\n"
                              "  --render    time the terminal front end instead: frame\n"
                              "              composition, and the bytes a terminal receives\n"
                              "              per frame of a break (through a pty)\n";

constexpr double break_speed = 12.0;        // m/s, a firm break
constexpr double break_angle_jitter = 0.5;  // degrees either way, so that breaks differ
constexpr double shot_min_speed = 1.0;      // m/s
constexpr double shot_max_speed = 4.0;      // m/s
constexpr double shot_max_tip_offset = 0.3; // fraction of R, either way
// A snooker break: from the D, thin off the back red nearest the cue ball (the line of aim
// break_clip = 1.6 R off its centre: a cut of 53 degrees), at a firm 7 m/s. Its aim is jittered
// less than the 8-ball break's: half a degree over two metres would move the line by 19 mm, from a
// thin hit to a miss or to the side of the pack.
constexpr double snooker_break_speed = 7.0;        // m/s
constexpr double snooker_break_angle_jitter = 0.1; // degrees either way

// The cost per event against the number of balls: N balls (the cue ball and a triangle of N - 1)
// on the 9 ft table scaled by sqrt(N / 16) each way, so that 16 balls break on the 9 ft table
// itself and the balls have the same room per ball at every N; the break as the 8-ball one.
constexpr std::size_t most_balls = 1024;
constexpr std::size_t most_ball_counts = 16;     // rows in one run
constexpr std::uint64_t most_ball_runs = 100000; // breaks a row
constexpr double rack_gap = 2e-4;                // m between neighbours in the triangle

struct Options {
    std::uint64_t breaks = 1000;
    std::uint64_t shots = 10000;
    std::uint64_t seed = 1;
    std::vector<std::size_t> balls = {16, 32, 64, 128};
    std::uint64_t ball_runs = 100;
    bool render = false;
};

/// "16,32,64" as ball counts, each 2..most_balls, at most most_ball_counts of them; nothing for
/// anything else.
std::optional<std::vector<std::size_t>> parse_ball_counts(const std::string& text) {
    std::vector<std::size_t> counts;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const std::optional<std::uint64_t> n = parse_uint64(text.substr(start, comma - start));
        if (!n || *n < 2 || *n > most_balls || counts.size() == most_ball_counts)
            return std::nullopt;
        counts.push_back(static_cast<std::size_t>(*n));
        start = comma + 1;
    }
    return counts;
}

/// The options, or nothing after a message on stderr (bad usage) or on stdout (--help).
std::optional<Options> parse_options(const std::vector<std::string>& args, bool& help) {
    Options options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string name = args[i];
        if (name == "-h" || name == "--help") {
            help = true;
            return std::nullopt;
        }
        if (name == "--render") {
            options.render = true;
            continue;
        }
        std::optional<std::string> value;
        if (const std::size_t eq = name.find('=');
            name.starts_with("--") && eq != std::string::npos) {
            value = name.substr(eq + 1);
            name.resize(eq);
        } else if (i + 1 < args.size()) {
            value = args[++i];
        }
        if (name == "--balls") {
            const auto counts = value ? parse_ball_counts(*value) : std::nullopt;
            if (!counts) {
                std::fprintf(stderr,
                             "termpool bench: --balls needs up to %zu ball counts 2..%zu, "
                             "such as 16,32,64,128\n",
                             most_ball_counts, most_balls);
                return std::nullopt;
            }
            options.balls = *counts;
            continue;
        }
        std::uint64_t* target = name == "--breaks"      ? &options.breaks
                                : name == "--shots"     ? &options.shots
                                : name == "--seed"      ? &options.seed
                                : name == "--ball-runs" ? &options.ball_runs
                                                        : nullptr;
        if (!target) {
            std::fprintf(stderr, "termpool bench: unknown option '%s'\n", name.c_str());
            return std::nullopt;
        }
        const std::optional<std::uint64_t> number =
            value ? parse_uint64(*value) : std::optional<std::uint64_t>{};
        if (!number) {
            std::fprintf(stderr, "termpool bench: %s needs a non-negative integer\n", name.c_str());
            return std::nullopt;
        }
        *target = *number;
    }
    if (options.ball_runs > most_ball_runs) {
        std::fprintf(stderr, "termpool bench: --ball-runs is at most %llu\n",
                     static_cast<unsigned long long>(most_ball_runs));
        return std::nullopt;
    }
    if (options.breaks == 0) {
        std::fputs("termpool bench: --breaks must be at least 1\n", stderr);
        return std::nullopt;
    }
    return options;
}

/// Per-run timings and event counts of one part of the benchmark.
struct Sample {
    std::vector<double> micros;     ///< wall time of each run
    std::vector<double> cpu_micros; ///< this thread's CPU time of each run
    std::uint64_t events = 0;
    std::uint64_t cut_short = 0; ///< runs that hit World::max_events
    StateDigest outcomes;        ///< every run's events and final balls, to the bit
};

/// Runs one shot and adds its time, events and outcome to `sample`.
ShotResult timed_shot(const Table& table, const PhysicsParams& params,
                      const std::vector<Ball>& balls, const Strike& strike, Sample& sample) {
    // The CPU clock's reads bracket the wall clock's, so that their cost (a system call each,
    // well under a microsecond) stays out of the wall figure.
    const double cpu_start = thread_cpu_seconds();
    const auto start = std::chrono::steady_clock::now();
    ShotResult result = simulate_shot(table, params, balls, strike);
    const auto stop = std::chrono::steady_clock::now();
    sample.cpu_micros.push_back(1e6 * (thread_cpu_seconds() - cpu_start));
    sample.micros.push_back(std::chrono::duration<double, std::micro>(stop - start).count());
    sample.events += result.events.size();
    sample.cut_short += result.event_limit_hit ? 1 : 0;
    sample.outcomes.add(static_cast<std::uint64_t>(result.events.size()));
    sample.outcomes.add(result.rest_time);
    sample.outcomes.add(result.balls);
    return result;
}

/// The balls left on the table after a break, ready for another shot; nothing if the cue ball
/// went down and its place (`cue_spot`: the head spot, or in the D) is taken.
std::optional<std::vector<Ball>> next_layout(const ShotResult& result, Vec2 cue_spot,
                                             const PhysicsParams& params) {
    std::vector<Ball> balls;
    bool cue_pocketed = false;
    for (const Ball& b : result.balls) {
        if (b.state != MotionState::pocketed) {
            balls.push_back(b);
        } else if (b.id == 0) {
            cue_pocketed = true;
        }
    }
    if (cue_pocketed) {
        const Vec2 spot = cue_spot;
        for (const Ball& b : balls)
            if (length(b.position - spot) < 2 * params.ball_radius)
                return std::nullopt;
        Ball cue;
        cue.id = 0;
        cue.mass = params.ball_mass;
        cue.position = spot;
        balls.insert(balls.begin(), cue);
    }
    return balls;
}

double percentile(std::vector<double> values, double fraction) {
    std::sort(values.begin(), values.end());
    // Nearest rank, so that the figure is one that was measured.
    const auto rank = static_cast<std::size_t>(std::ceil(fraction * values.size()));
    return values[std::max<std::size_t>(rank, 1) - 1];
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

void print_row(const char* label, const Sample& s) {
    if (s.micros.empty()) {
        std::printf("%-18s %8d %11s %9s %11s %12s %12s %10s\n", label, 0, "-", "-", "-", "-", "-",
                    "-");
        return;
    }
    double total = 0;
    for (double m : s.micros)
        total += m;
    const double runs = static_cast<double>(s.micros.size());
    std::printf("%-18s %8zu %11.1f %9.1f %11.1f %12.1f %12.0f %10.0f\n", label, s.micros.size(),
                median(s.micros), percentile(s.micros, 0.95), median(s.cpu_micros), s.events / runs,
                s.events / (total * 1e-6), runs / (total * 1e-6));
}

/// The processor's name from /proc/cpuinfo, where there is one.
std::string cpu_name() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);) {
        if (!line.starts_with("model name"))
            continue;
        const std::size_t colon = line.find(':');
        if (colon != std::string::npos)
            return line.substr(line.find_first_not_of(" \t", colon + 1));
    }
    return "unknown processor";
}

/// The breaks and the shots of one game, and how many layouts they left.
struct Part {
    Sample breaks;
    Sample shots;
    std::size_t layouts = 0;
    std::uint64_t unusable = 0;
};

/// Random strikes on `layouts`, taken in turn.
void time_shots(const Table& table, const PhysicsParams& params,
                const std::vector<std::vector<Ball>>& layouts, std::uint64_t count, Random& rng,
                Sample& shots) {
    for (std::uint64_t k = 0; k < count && !layouts.empty(); ++k) {
        Strike strike;
        strike.speed = rng.uniform(shot_min_speed, shot_max_speed);
        strike.angle_deg = rng.uniform(0, 360);
        strike.side = rng.uniform(-shot_max_tip_offset, shot_max_tip_offset);
        strike.follow = rng.uniform(-shot_max_tip_offset, shot_max_tip_offset);
        timed_shot(table, params, layouts[k % layouts.size()], strike, shots);
    }
}

double degrees_of(Vec2 v) {
    return portable::atan2(v.y, v.x) * 180.0 / std::numbers::pi;
}

/// Seeded 8-ball breaks on the 9 ft table, then random shots on what they leave.
Part eight_ball_part(const Options& options, Random& rng) {
    const Table table = make_table(TableSize::nine_foot);
    const PhysicsParams params;
    // Breaks: the cue ball on the head spot aimed at the apex ball on the foot spot.
    const double aim_deg = degrees_of(table.foot_spot() - table.head_spot());
    Part part;
    std::vector<std::vector<Ball>> layouts;
    for (std::uint64_t seed = 1; seed <= options.breaks; ++seed) {
        const std::vector<Ball> rack = make_rack(table, params, RackType::eight_ball, seed);
        const double angle = aim_deg + rng.uniform(-break_angle_jitter, break_angle_jitter);
        const ShotResult result =
            timed_shot(table, params, rack, Strike{break_speed, angle, 0, 0}, part.breaks);
        auto layout =
            result.event_limit_hit ? std::nullopt : next_layout(result, table.head_spot(), params);
        if (layout)
            layouts.push_back(std::move(*layout));
        else
            ++part.unusable;
    }
    time_shots(table, params, layouts, options.shots, rng, part.shots);
    part.layouts = layouts.size();
    return part;
}

/// Seeded snooker breaks (22 balls) on the snooker table with snooker balls, then random
/// shots on what they leave.
Part snooker_part(const Options& options, Random& rng) {
    const PhysicsParams params = physics_for_table(TableSize::snooker);
    const Table table = make_table(TableSize::snooker, params.ball_radius);
    // Snooker's default break-off line: thin off the end red (break_aim_deg).
    const GameRow& snooker = game_row(*parse_game_type("snooker"));
    Part part;
    std::vector<std::vector<Ball>> layouts;
    for (std::uint64_t seed = 1; seed <= options.breaks; ++seed) {
        const std::vector<Ball> rack = make_rack(table, params, RackType::snooker, seed);
        const double angle = break_aim_deg(snooker, rack, params.ball_radius) +
                             rng.uniform(-snooker_break_angle_jitter, snooker_break_angle_jitter);
        const ShotResult result =
            timed_shot(table, params, rack, Strike{snooker_break_speed, angle, 0, 0}, part.breaks);
        auto layout = result.event_limit_hit ? std::nullopt
                                             : next_layout(result, rack.front().position, params);
        if (layout)
            layouts.push_back(std::move(*layout));
        else
            ++part.unusable;
    }
    time_shots(table, params, layouts, options.shots, rng, part.shots);
    part.layouts = layouts.size();
    return part;
}

/// The cue ball on the head spot and a triangle of `count - 1` balls from the foot spot on, each
/// a little apart from its neighbours (a gap drawn per ball, so that runs differ).
std::vector<Ball> scaled_rack(const Table& table, const PhysicsParams& params, std::size_t count,
                              Random& rng) {
    const double R = params.ball_radius;
    std::vector<Ball> balls(count);
    balls[0].position = table.head_spot();
    // Rows a gap's width wider than touching, so that no two balls touch before the break.
    const double spacing = R + 0.5 * rack_gap;
    const double row_step = std::sqrt(3.0) * spacing;
    std::size_t placed = 1;
    for (int row = 0; placed < count; ++row) {
        for (int k = 0; k <= row && placed < count; ++k, ++placed) {
            balls[placed].position = {table.foot_spot().x + row * row_step,
                                      table.foot_spot().y + (2 * k - row) * spacing +
                                          rng.uniform(-0.25, 0.25) * rack_gap};
        }
    }
    for (std::size_t i = 0; i < count; ++i) {
        balls[i].id = static_cast<int>(i);
        balls[i].mass = params.ball_mass;
    }
    return balls;
}

/// One row of the cost per event against the number of balls.
struct BallsRow {
    std::size_t balls = 0;
    Sample breaks;
};

BallsRow balls_row(std::size_t count, std::uint64_t runs, Random& rng) {
    const PhysicsParams params;
    const double scale = std::sqrt(static_cast<double>(count) / 16.0);
    const Table nine_foot = make_table(TableSize::nine_foot);
    const Table table = make_table(nine_foot.length * scale, nine_foot.width * scale,
                                   params.ball_radius, pocket_spec(TableSize::nine_foot));
    BallsRow row;
    row.balls = count;
    // One world, reset for each run outside the timing: the row is the cost of the events, not
    // of setting balls out.
    World world(table, params, scaled_rack(table, params, count, rng));
    const double aim_deg = degrees_of(table.foot_spot() - table.head_spot());
    std::vector<Ball> final_balls;
    for (std::uint64_t run = 0; run < runs; ++run) {
        world.reset(scaled_rack(table, params, count, rng));
        const Strike strike{break_speed,
                            aim_deg + rng.uniform(-break_angle_jitter, break_angle_jitter), 0, 0};
        std::uint64_t events = 0;
        const double cpu_start = thread_cpu_seconds();
        const auto start = std::chrono::steady_clock::now();
        world.strike(strike);
        while (world.step())
            ++events;
        const auto stop = std::chrono::steady_clock::now();
        row.breaks.cpu_micros.push_back(1e6 * (thread_cpu_seconds() - cpu_start));
        row.breaks.micros.push_back(
            std::chrono::duration<double, std::micro>(stop - start).count());
        row.breaks.events += events;
        row.breaks.cut_short += world.at_rest() ? 0 : 1;
        world.balls(final_balls);
        row.breaks.outcomes.add(events);
        row.breaks.outcomes.add(world.time());
        row.breaks.outcomes.add(final_balls);
    }
    return row;
}

double sum(const std::vector<double>& values) {
    double total = 0;
    for (const double v : values)
        total += v;
    return total;
}

void print_balls_rows(const std::vector<BallsRow>& rows, std::uint64_t runs) {
    std::printf("\ncost per event against the number of balls: the cue ball and a triangle of "
                "N - 1 on the 9ft table scaled by sqrt(N/16), broken at %s m/s, %llu runs each\n",
                format_number(break_speed).c_str(), static_cast<unsigned long long>(runs));
    std::printf("%-18s %12s %12s %12s %12s\n", "balls", "events/run", "ns/event", "CPU ns/event",
                "CPU med us");
    StateDigest outcomes;
    for (const BallsRow& row : rows) {
        const double events = static_cast<double>(std::max<std::uint64_t>(row.breaks.events, 1));
        std::printf("%-18zu %12.1f %12.1f %12.1f %12.1f\n", row.balls,
                    row.breaks.events / static_cast<double>(row.breaks.micros.size()),
                    1e3 * sum(row.breaks.micros) / events,
                    1e3 * sum(row.breaks.cpu_micros) / events, median(row.breaks.cpu_micros));
        outcomes.add(row.breaks.outcomes.value());
    }
    if (rows.size() > 1) {
        const auto cpu_per_event = [](const BallsRow& r) {
            return sum(r.breaks.cpu_micros) /
                   static_cast<double>(std::max<std::uint64_t>(r.breaks.events, 1));
        };
        std::printf("%zu balls: %.2f times the CPU cost per event of %zu\n", rows.back().balls,
                    cpu_per_event(rows.back()) / cpu_per_event(rows.front()), rows.front().balls);
    }
    std::printf("hash of these outcomes: %s\n", digest_hex(outcomes.value()).c_str());
}

} // namespace

int bench_command(const std::vector<std::string>& args, RenderBench render) {
    bool help = false;
    const std::optional<Options> parsed = parse_options(args, help);
    if (!parsed) {
        std::fputs(usage, help ? stdout : stderr);
        return help ? 0 : 2;
    }
    const Options options = *parsed;
    if (options.render)
        return render(cpu_name());
    Random rng(options.seed);
    const Part eight = eight_ball_part(options, rng);
    // Its own stream, so that the 8-ball figures are those of a bench without snooker.
    Random snooker_rng(options.seed ^ 0x5a00cce7ULL);
    const Part snooker = snooker_part(options, snooker_rng);

    std::printf("termpool bench: 8-ball on the 9ft table, snooker on the snooker table with "
                "snooker balls; default physics, seed %llu\n",
                static_cast<unsigned long long>(options.seed));
    std::printf("measured on one core (single thread) of: %s\n\n", cpu_name().c_str());
    std::printf("%-18s %8s %11s %9s %11s %12s %12s %10s\n", "", "runs", "median us", "p95 us",
                "CPU med us", "events/run", "events/s", "runs/s");
    print_row("breaks (12 m/s)", eight.breaks);
    print_row("shots (1-4 m/s)", eight.shots);
    print_row("snooker breaks", snooker.breaks);
    print_row("snooker shots", snooker.shots);
    std::printf("\n");
    std::printf("median us, p95 us, events/s, runs/s: wall time; CPU med us: the median of this "
                "thread's CPU time a run\n");
    std::printf("breaks: racks seeded 1..%llu, aimed at the apex +-%s deg\n",
                static_cast<unsigned long long>(options.breaks),
                format_number(break_angle_jitter).c_str());
    std::printf("snooker breaks: 22 balls, racks seeded 1..%llu, from the D at %s m/s, thin "
                "on the back corner red +-%s deg\n",
                static_cast<unsigned long long>(options.breaks),
                format_number(snooker_break_speed).c_str(),
                format_number(snooker_break_angle_jitter).c_str());
    std::printf("shots:  speed 1..4 m/s, any angle, tip offsets within +-%s R, on the %zu (8-ball) "
                "and %zu (snooker) break layouts in turn\n",
                format_number(shot_max_tip_offset).c_str(), eight.layouts, snooker.layouts);
    const std::uint64_t unusable = eight.unusable + snooker.unusable;
    if (unusable > 0)
        std::printf("        (%llu layouts left out: cut short, or the cue ball pocketed and its "
                    "spot taken)\n",
                    static_cast<unsigned long long>(unusable));
    // So that two machines or builds can compare runs at a glance.
    StateDigest outcomes;
    for (const Sample* s : {&eight.breaks, &eight.shots, &snooker.breaks, &snooker.shots})
        outcomes.add(s->outcomes.value());
    std::printf("hash of every outcome (events, positions, velocities, spins): %s\n",
                digest_hex(outcomes.value()).c_str());
    std::uint64_t cut_short = eight.breaks.cut_short + eight.shots.cut_short +
                              snooker.breaks.cut_short + snooker.shots.cut_short;
    if (options.ball_runs > 0) {
        Random balls_rng(options.seed ^ 0xba115ULL);
        std::vector<BallsRow> rows;
        for (const std::size_t count : options.balls) {
            rows.push_back(balls_row(count, options.ball_runs, balls_rng));
            cut_short += rows.back().breaks.cut_short;
        }
        print_balls_rows(rows, options.ball_runs);
    }
    if (cut_short > 0)
        std::printf("warning: %llu runs stopped at the limit of %zu events\n",
                    static_cast<unsigned long long>(cut_short), World::max_events);
    return 0;
}

} // namespace termpool::cli
