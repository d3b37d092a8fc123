// `termpool selfplay`: computer against computer, headless, with the referee's invariants
// checked after every shot.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <optional>
#include <string>
#include <termpool/game_registry.hpp>
#include <termpool/match.hpp>
#include <termpool/safe_player.hpp>
#include <thread>
#include <vector>

#include "cli/commands.hpp"
#include "cli/cpu_clock.hpp"
#include "cli/numbers.hpp"

namespace termpool::cli {
namespace {

constexpr const char* usage =
    "usage: termpool selfplay --games N --p1 LEVEL --p2 LEVEL\n"
    "                         [--game 8ball|8ball-bar|9ball|10ball|snooker] [--seed S] [--jobs J]\n"
    "  LEVEL is easy, medium, hard or pro; games alternate the breaker.\n"
    "  Snooker also takes LEVEL safe: a scripted opponent that pots only an easy ball and\n"
    "  otherwise plays safe.\n";

constexpr int max_shots_per_game = 500;

struct Options {
    std::uint64_t games = 0;
    Level levels[2] = {Level::medium, Level::medium};
    bool safe[2] = {false, false}; // the seat is the scripted safe player, not a computer level
    bool level_given[2] = {false, false};
    GameType game = default_game;
    std::uint64_t seed = 1;
    std::uint64_t jobs = 1;
};

struct SeatFigures {
    std::uint64_t decisions = 0;
    double seconds = 0;          // CPU time of its decisions
    double longest_decision = 0; // the slowest decision (a shot, a placing and its shot, a choice)
    std::uint64_t simulations = 0;
    std::uint64_t pot_attempts = 0;
    std::uint64_t pots = 0;
    // Snooker: the frame's score, its highest break, and the visits to the table (a visit is
    // a run of shots by one player) with the balls potted in them.
    int frame_score = 0;
    int highest_break = 0;
    int centuries = 0; // frames with a break of 100 or more (one frame holds at most one)
    // Pot attempts and pots as the players' statistics count them (StatsTally): every shot
    // but a break or a called safety is an attempt.
    std::uint64_t tally_attempts = 0;
    std::uint64_t tally_pots = 0;
    std::uint64_t visits = 0;
    std::uint64_t balls_potted = 0;
    std::uint64_t fouls = 0;
};

struct GameSummary {
    int winner = 0;
    WinReason reason = WinReason::none;
    int shots = 0;
    int fouls = 0;
    bool break_and_run = false;
    SeatFigures players[2];
    std::string violation; // empty when every invariant held
};

std::optional<Options> parse(const std::vector<std::string>& args, std::string& error) {
    Options o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& name = args[i];
        if (i + 1 >= args.size()) {
            error = name + " needs a value";
            return std::nullopt;
        }
        const std::string& value = args[++i];
        if (name == "--games" || name == "--seed" || name == "--jobs") {
            const auto n = parse_uint64(value);
            if (!n) {
                error = name + " needs a non-negative integer";
                return std::nullopt;
            }
            (name == "--games" ? o.games : name == "--seed" ? o.seed : o.jobs) = *n;
        } else if (name == "--p1" || name == "--p2") {
            const int p = name == "--p1" ? 0 : 1;
            const auto level = parse_level(value);
            if (!level && value != "safe") {
                error = "unknown level '" + value + "' (easy, medium, hard, pro or safe)";
                return std::nullopt;
            }
            o.levels[p] = level.value_or(Level::hard);
            o.safe[p] = !level;
            o.level_given[p] = true;
        } else if (name == "--game") {
            const auto g = parse_game_type(value);
            if (!g) {
                error = "unknown game '" + value + "'";
                return std::nullopt;
            }
            o.game = *g;
        } else {
            error = "unknown option '" + name + "'";
            return std::nullopt;
        }
    }
    if (o.games == 0 || !o.level_given[0] || !o.level_given[1]) {
        error = "--games (at least 1), --p1 and --p2 are required";
        return std::nullopt;
    }
    if ((o.safe[0] || o.safe[1]) && game_row(o.game).balls != BallSet::snooker) {
        error = "the safe player plays snooker only (--game snooker)";
        return std::nullopt;
    }
    o.jobs = std::clamp<std::uint64_t>(o.jobs, 1, 64);
    return o;
}

// The invariants every shot must keep; a message when one is broken.
std::string check_invariants(const Game& game) {
    const GameRow& row = game_row(game.type());
    const int last_ball = rack_last_ball(row.rack);
    const std::size_t count = static_cast<std::size_t>(last_ball) + 1;
    if (game.balls().size() != count)
        return "balls on the table and in pockets do not add up";
    for (int want = 0; want <= last_ball; ++want) {
        if (std::ranges::count_if(game.balls(), [&](const Ball& b) { return b.id == want; }) != 1)
            return "ball " + std::to_string(want) + " is not accounted for exactly once";
    }
    const double R = game.params().ball_radius;
    for (std::size_t i = 0; i < game.balls().size(); ++i)
        for (std::size_t j = i + 1; j < game.balls().size(); ++j) {
            const Ball &a = game.balls()[i], &b = game.balls()[j];
            if (a.state == MotionState::pocketed || b.state == MotionState::pocketed)
                continue;
            if (length(a.position - b.position) < 2 * R - 1e-9)
                return "balls " + std::to_string(a.id) + " and " + std::to_string(b.id) +
                       " overlap";
        }
    if (game.shooter() != 1 && game.shooter() != 2)
        return "no single shooter";
    // Snooker: while reds remain every colour is on the table (they are re-spotted).
    if (row.balls == BallSet::snooker &&
        std::ranges::any_of(game.balls(),
                            [](const Ball& b) {
                                return b.id >= 1 && b.id <= 15 && b.state != MotionState::pocketed;
                            }) &&
        std::ranges::any_of(game.balls(), [](const Ball& b) {
            return b.id >= 16 && b.state == MotionState::pocketed;
        }))
        return "a colour is missing while reds remain";
    // 9-ball, 10-ball: the deciding ball comes back whenever it drops without winning.
    const int money = row.deciding_ball;
    if (row.push_out && game.winner() == 0 && std::ranges::any_of(game.balls(), [&](const Ball& b) {
            return b.id == money && b.state == MotionState::pocketed;
        }))
        return "the " + std::to_string(money) + " is down and the game goes on";
    if (money != 9 && game.win_reason() == WinReason::nine_pocketed)
        return std::string("a ") + row.title + " game won by the 9";
    return {};
}

// The move of the player to act: the seated computer's, or the scripted safe player's (a
// person's seat to the match). Nothing when neither may act.
std::optional<ComputerMove> move_of(Match& match, std::optional<SafePlayer> (&scripted)[2]) {
    const PendingAction pending = match.pending();
    if (pending.player != 1 && pending.player != 2)
        return std::nullopt;
    std::optional<SafePlayer>& safe = scripted[pending.player - 1];
    if (!safe)
        return match.computer_move();
    const Game& game = match.game();
    ComputerMove move;
    move.kind = pending.kind;
    if (safe->concedes(game)) {
        move.kind = Pending::choose;
        move.choice = Choice::concede;
    } else if (pending.kind == Pending::place) {
        move.spot = safe->place_cue_ball(game);
    } else if (pending.kind == Pending::choose) {
        move.choice = safe->choose(game);
    } else if (pending.kind == Pending::shoot) {
        move.shot = safe->shot(game);
    } else {
        return std::nullopt;
    }
    return move;
}

GameSummary play_one(const Options& o, std::uint64_t index) {
    GameSummary summary;
    GameRecord header;
    header.setup.game = o.game;
    header.seed = o.seed * 1000003ULL + index;
    header.breaker = 1 + static_cast<int>(index % 2);
    std::optional<SafePlayer> scripted[2];
    for (int p = 0; p < 2; ++p) {
        if (!o.safe[p])
            header.computers[p] = o.levels[p];
        else // a stream apart from every computer's
            scripted[p].emplace((header.seed * 2 + static_cast<std::uint64_t>(p) + 1) ^
                                0x5afe5afe5afe5afeULL);
    }
    // Seat p's computer plays from seed 2 * seed + p.
    auto started = Match::start(header, header.seed * 2);
    if (const MatchError* refused = std::get_if<MatchError>(&started)) {
        summary.violation =
            std::string("the match refused its setup: ") + match_error_text(*refused);
        return summary;
    }
    Match& match = std::get<Match>(started);
    bool opponent_shot = false;
    int last_actor = 0;
    while (match.pending().kind != Pending::over) {
        if (summary.shots >= max_shots_per_game) {
            summary.violation =
                "the game did not end within " + std::to_string(max_shots_per_game) + " shots";
            return summary;
        }
        const int actor = match.to_act();
        SeatFigures& stats = summary.players[actor - 1];
        const double start = thread_cpu_seconds();
        const std::uint64_t simulated = match.computer_simulations(actor);
        std::optional<ComputerMove> move = move_of(match, scripted);
        if (move && move->kind == Pending::choose) {
            stats.longest_decision = std::max(stats.longest_decision, thread_cpu_seconds() - start);
            if (match.choose(actor, move->choice) != MatchError::none) {
                summary.violation = "a choice the match refused";
                return summary;
            }
            continue;
        }
        if (move && move->kind == Pending::place) {
            if (match.place(actor, move->spot) != MatchError::none) {
                summary.violation = "illegal ball-in-hand placement";
                return summary;
            }
            move = move_of(match, scripted);
        }
        if (!move || move->kind != Pending::shoot) {
            summary.violation = "the computer had no shot to play";
            return summary;
        }
        const ComputerShot& shot = move->shot;
        const double took = thread_cpu_seconds() - start;
        stats.seconds += took;
        stats.longest_decision = std::max(stats.longest_decision, took);
        stats.simulations += match.computer_simulations(actor) - simulated;
        ++stats.decisions;
        const auto played = match.shoot(actor, shot.strike, shot.call);
        if (const MatchError* refused = std::get_if<MatchError>(&played)) {
            summary.violation =
                std::string("the match refused the shot: ") + match_error_text(*refused);
            return summary;
        }
        const PlayedShot& p = std::get<PlayedShot>(played);
        ++summary.shots;
        if (actor != header.breaker)
            opponent_shot = true;
        if (actor != last_actor)
            ++stats.visits;
        last_actor = actor;
        if (p.verdict.foul != Foul::none) {
            ++summary.fouls;
            ++stats.fouls;
        } else {
            stats.balls_potted += static_cast<std::uint64_t>(
                std::ranges::count_if(p.verdict.pocketed, [](int id) { return id != 0; }));
        }
        // A snooker nomination without a pocket is a safety on a colour, not a pot tried.
        const bool pot_tried =
            shot.call.call.ball != 0 &&
            (game_row(o.game).calls != CallRule::ball_on || shot.call.call.pocket != 0);
        if (!p.was_break && pot_tried) {
            ++stats.pot_attempts;
            if (std::ranges::count(p.verdict.pocketed, shot.call.call.ball) &&
                p.verdict.foul == Foul::none)
                ++stats.pots;
        }
        if (std::string problem = check_invariants(match.game()); !problem.empty()) {
            summary.violation = problem + " after shot " + std::to_string(summary.shots);
            return summary;
        }
    }
    for (int seat = 1; seat <= 2; ++seat) {
        summary.players[seat - 1].frame_score = match.game().score_of(seat);
        summary.players[seat - 1].highest_break = match.game().snooker().highest_break[seat - 1];
        summary.players[seat - 1].centuries = summary.players[seat - 1].highest_break >= 100;
        summary.players[seat - 1].tally_attempts =
            static_cast<std::uint64_t>(match.tally().of(seat).pot_attempts);
        summary.players[seat - 1].tally_pots =
            static_cast<std::uint64_t>(match.tally().of(seat).pots_made);
    }
    summary.winner = match.game().winner();
    summary.reason = match.game().win_reason();
    summary.break_and_run = summary.winner == header.breaker && !opponent_shot;
    return summary;
}

// The seat's player as the summary names it: its level, or "safe".
const char* seat_name(const Options& o, int p) {
    return o.safe[p] ? "safe" : level_name(o.levels[p]);
}

// 95% Wilson interval of a proportion, in percent.
std::pair<double, double> wilson(double wins, double n) {
    const double z = 1.96, p = wins / n;
    const double centre = (p + z * z / (2 * n)) / (1 + z * z / n);
    const double half = z * std::sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n);
    return {std::max(0.0, 100 * (centre - half)), std::min(100.0, 100 * (centre + half))};
}

} // namespace

int selfplay_command(const std::vector<std::string>& args) {
    if (std::ranges::any_of(args,
                            [](const std::string& a) { return a == "-h" || a == "--help"; })) {
        std::fputs(usage, stdout);
        return 0;
    }
    std::string error;
    const auto options = parse(args, error);
    if (!options) {
        std::fprintf(stderr, "termpool selfplay: %s\n%s", error.c_str(), usage);
        return 2;
    }
    const Options& o = *options;
    std::vector<GameSummary> records(o.games);
    std::atomic<std::uint64_t> next{0};
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = process_cpu_seconds(); // all jobs' threads
    auto worker = [&] {
        for (std::uint64_t i = next++; i < o.games; i = next++)
            records[i] = play_one(o, i);
    };
    std::vector<std::thread> threads;
    for (std::uint64_t j = 1; j < o.jobs; ++j)
        threads.emplace_back(worker);
    worker();
    for (std::thread& t : threads)
        t.join();
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu = process_cpu_seconds() - cpu_start;

    int wins[2] = {0, 0};
    std::uint64_t fouls = 0, shots = 0, runs = 0;
    SeatFigures per[2];
    for (std::uint64_t i = 0; i < o.games; ++i) {
        const GameSummary& r = records[i];
        if (!r.violation.empty()) {
            std::fprintf(
                stderr, "termpool selfplay: invariant broken in game %llu (seed %llu): %s\n",
                static_cast<unsigned long long>(i + 1),
                static_cast<unsigned long long>(o.seed * 1000003ULL + i), r.violation.c_str());
            return 3;
        }
        std::printf("game %llu winner %d %s shots %d fouls %d break-and-run %s\n",
                    static_cast<unsigned long long>(i + 1), r.winner, win_reason_name(r.reason),
                    r.shots, r.fouls, r.break_and_run ? "yes" : "no");
        ++wins[r.winner - 1];
        fouls += r.fouls;
        shots += r.shots;
        runs += r.break_and_run;
        for (int p = 0; p < 2; ++p) {
            per[p].decisions += r.players[p].decisions;
            per[p].seconds += r.players[p].seconds;
            per[p].longest_decision =
                std::max(per[p].longest_decision, r.players[p].longest_decision);
            per[p].centuries += r.players[p].centuries;
            per[p].tally_attempts += r.players[p].tally_attempts;
            per[p].tally_pots += r.players[p].tally_pots;
            per[p].simulations += r.players[p].simulations;
            per[p].pot_attempts += r.players[p].pot_attempts;
            per[p].pots += r.players[p].pots;
            per[p].frame_score += r.players[p].frame_score;
            per[p].highest_break = std::max(per[p].highest_break, r.players[p].highest_break);
            per[p].visits += r.players[p].visits;
            per[p].balls_potted += r.players[p].balls_potted;
            per[p].fouls += r.players[p].fouls;
        }
    }
    const double n = static_cast<double>(o.games);
    std::printf("\n%s, %llu games, seed %llu\n", game_type_name(o.game),
                static_cast<unsigned long long>(o.games), static_cast<unsigned long long>(o.seed));
    for (int p = 0; p < 2; ++p) {
        const auto [lo, hi] = wilson(wins[p], n);
        const SeatFigures& s = per[p];
        std::printf("p%d %-6s wins %4d (%.1f%%, 95%% CI %.1f-%.1f%%)  pots %.1f%% of %llu  "
                    "decision %.3f s (max %.3f s) CPU  %.0f shots/s\n",
                    p + 1, seat_name(o, p), wins[p], 100 * wins[p] / n, lo, hi,
                    s.pot_attempts ? 100.0 * s.pots / s.pot_attempts : 0.0,
                    static_cast<unsigned long long>(s.pot_attempts),
                    s.decisions ? s.seconds / s.decisions : 0.0, s.longest_decision,
                    s.seconds > 0 ? s.simulations / s.seconds : 0.0);
    }
    if (game_row(o.game).scoring == Scoring::points)
        for (int p = 0; p < 2; ++p) {
            const SeatFigures& s = per[p];
            std::printf("p%d %-6s frame score %.1f  highest break %d  centuries %d  "
                        "pots per visit %.2f  fouls per frame %.2f\n",
                        p + 1, seat_name(o, p), s.frame_score / n, s.highest_break, s.centuries,
                        s.visits ? static_cast<double>(s.balls_potted) / s.visits : 0.0,
                        s.fouls / n);
            // The statistics count every shot but a break or a called safety: a safety on a
            // nominated colour, say, is a pot missed there.
            std::printf("p%d %-6s pots as the statistics count them %.1f%% of %llu\n", p + 1,
                        seat_name(o, p),
                        s.tally_attempts ? 100.0 * s.tally_pots / s.tally_attempts : 0.0,
                        static_cast<unsigned long long>(s.tally_attempts));
        }
    std::printf("fouls per game %.2f, shots per game %.1f, break-and-runs %llu (%.1f%%), "
                "%.1f s wall, %.1f s CPU\n",
                fouls / n, shots / n, static_cast<unsigned long long>(runs), 100 * runs / n, wall,
                cpu);
    return 0;
}

} // namespace termpool::cli
