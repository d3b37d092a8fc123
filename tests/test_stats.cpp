// Player statistics: the tally of a game's shots, the totals file (text form, damaged files
// kept aside, atomic writes), the game-over summary and `termpool stats`.
#include <catch2/catch.hpp>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <termpool/computer.hpp>
#include <termpool/match.hpp>
#include <termpool/snooker_layout.hpp>
#include <termpool/stats.hpp>

#include <unistd.h>

#include "cli/stats_command.hpp"
#include "file_helpers.hpp"
#include "files/atomic_file.hpp"
#include "files/read_file.hpp"
#include "player/stats_file.hpp"
#include "player/stats_summary.hpp"
#include "record_helpers.hpp"
#include "rules_helpers.hpp"
#include <termpool/text_width.hpp>

using namespace termpool;
using namespace termpool::test;
using namespace termpool::cli;
using termpool::StatsStore;

#include "lines_of.hpp"
#include "match_helpers.hpp"
#include "temp_dir.hpp"

namespace {

// ---------------------------------------------------------------------------------------------
// Hand-made verdicts

/// A legal shot potting `balls`; the shooter keeps the table when anything dropped.
Verdict potted(int shooter, std::vector<int> balls) {
    Verdict v;
    v.pocketed = std::move(balls);
    v.next_shooter = v.pocketed.empty() ? 3 - shooter : shooter;
    return v;
}

/// A legal shot that wins the rack for `shooter`, potting `balls`.
Verdict wins(int shooter, std::vector<int> balls) {
    Verdict v = potted(shooter, std::move(balls));
    v.winner = shooter;
    return v;
}

/// A foul (a scratch) that also drops `balls`.
Verdict foul(int shooter, std::vector<int> balls = {}) {
    Verdict v;
    v.foul = Foul::scratch;
    v.fouls = {Foul::scratch};
    v.pocketed = std::move(balls);
    v.pocketed.push_back(0);
    v.next_shooter = 3 - shooter;
    v.ball_in_hand = BallInHand::anywhere;
    return v;
}

const ShotCall plain;

/// Snooker: a shot without a foul by `shooter` that pots `balls` for `points`; they stay at
/// the table when it scored.
Verdict scores(int shooter, int points, std::vector<int> balls) {
    Verdict v = potted(shooter, std::move(balls));
    v.points = points;
    v.next_shooter = points > 0 ? shooter : 3 - shooter;
    return v;
}

/// Snooker: a foul by `shooter` that gives the opponent `penalty` points.
Verdict gives_away(int shooter, int penalty) {
    Verdict v = foul(shooter); // an in-off
    v.penalty = penalty;
    v.ball_in_hand = BallInHand::d;
    return v;
}

/// Snooker: `shooter` pots a red and then the black, `times` times over.
void reds_and_blacks(StatsTally& t, int shooter, int times) {
    for (int i = 0; i < times; ++i) {
        t.on_shot(shooter, false, plain, scores(shooter, 1, {1 + i}));
        t.on_shot(shooter, false, plain, scores(shooter, 7, {snooker_black}));
    }
}

ShotCall safety() {
    ShotCall c;
    c.call.safety = true;
    return c;
}

ShotCall push_out() {
    ShotCall c;
    c.push_out = true;
    return c;
}

// ---------------------------------------------------------------------------------------------
// Games played by the computer

/// Two computers play a seeded game to its end, every action recorded; `live` is fed each shot
/// as the game goes, as the front end would.
GameRecord computer_game(GameType type, std::uint64_t seed, StatsTally& live) {
    GameRecord record;
    record.setup.game = type;
    record.seed = seed;
    record.names[0] = "CPU 1 (medium)";
    record.names[1] = "CPU 2 (hard)";
    Game game(type, make_table(record.setup), record.setup.physics, record.breaker, seed);
    ComputerPlayer players[2] = {ComputerPlayer(Level::medium, seed),
                                 ComputerPlayer(Level::hard, seed + 1)};
    for (int turn = 0; turn < 300 && game.winner() == 0; ++turn)
        test::play_one_action(game, players, record, [&](const PlayedShot& shot) {
            live.on_shot(shot.shooter, shot.was_break, shot.call, shot.verdict);
        });
    return record;
}

// ---------------------------------------------------------------------------------------------
// Files

// Scratch directories of this file's own name.
struct StatsDir : termpool::test::TempDir {
    StatsDir() : termpool::test::TempDir("termpool-stats") {}
};

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void spill(const std::string& path, const std::string& text) {
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

/// The names of the files in `dir`, sorted.
std::vector<std::string> files_in(const std::string& dir) {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::string parse_error(const std::string& text) {
    const auto parsed = termpool::parse_stats(text);
    if (const auto* e = std::get_if<termpool::StatsError>(&parsed))
        return std::to_string(e->line) + ": " + e->message;
    return "";
}

/// What one run of the binary did.
struct Run {
    int status = -1;
    std::string out;
    std::string err;
};

/// Runs `termpool stats ARGS` with XDG_STATE_HOME at `state`.
Run run_stats(const TempDir& dir, const std::string& state, const std::string& args) {
    const char* bin = std::getenv("TERMPOOL_BIN");
    const std::string binary = bin && *bin ? bin : "build/termpool";
    const std::string out = dir.path() + "/stdout", err = dir.path() + "/stderr";
    const std::string command =
        "XDG_STATE_HOME='" + state + "' '" + binary + "' stats " + args + " >" + out + " 2>" + err;
    const int raw = std::system(command.c_str());
    Run r;
    r.status = raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

PlayerStats some_stats(int seed) {
    PlayerStats s;
    s.racks_won = seed % 2;
    s.racks_played = 1;
    s.shots = 10 + seed;
    s.pot_attempts = 8 + seed;
    s.pots_made = 5;
    s.balls_potted = 6;
    s.fouls = 1;
    s.break_and_runs = 0;
    s.longest_run = 2 + seed % 3;
    return s;
}

} // namespace

// =============================================================================================
// The tally

TEST_CASE("a break-and-run: the breaker wins the rack and the opponent never shoots", "[stats]") {
    StatsTally t(GameType::eight_ball);
    t.on_shot(1, true, plain, potted(1, {3, 11}));
    t.on_shot(1, false, plain, potted(1, {1}));
    t.on_shot(1, false, plain, potted(1, {2, 4}));
    t.on_shot(1, false, plain, wins(1, {8}));
    const PlayerStats& a = t.of(1);
    CHECK(a.break_and_runs == 1);
    CHECK(a.racks_won == 1);
    CHECK(a.racks_played == 1);
    CHECK(t.of(2).racks_played == 1);
    CHECK(t.of(2).racks_won == 0);
    CHECK(a.shots == 4);
    CHECK(a.balls_potted == 6);
    CHECK(a.longest_run == 6);  // the break's balls are part of the run
    CHECK(a.pot_attempts == 3); // the break is not an attempt
    CHECK(a.pots_made == 3);
}

TEST_CASE("no break-and-run once the opponent has shot, nor for a win from their break",
          "[stats]") {
    SECTION("the breaker misses, then wins") {
        StatsTally t(GameType::eight_ball);
        t.on_shot(1, true, plain, potted(1, {3}));
        t.on_shot(1, false, plain, potted(1, {})); // a miss
        t.on_shot(2, false, plain, potted(2, {}));
        t.on_shot(1, false, plain, wins(1, {8}));
        CHECK(t.of(1).racks_won == 1);
        CHECK(t.of(1).break_and_runs == 0);
    }
    SECTION("the breaker's opponent wins") {
        StatsTally t(GameType::eight_ball);
        t.on_shot(1, true, plain, potted(1, {}));
        t.on_shot(2, false, plain, wins(2, {9}));
        CHECK(t.of(2).racks_won == 1);
        CHECK(t.of(2).break_and_runs == 0);
        CHECK(t.of(1).break_and_runs == 0);
    }
    SECTION("a re-break starts the count again") {
        StatsTally t(GameType::eight_ball);
        t.on_shot(1, true, plain, potted(1, {})); // an illegal break: the opponent re-racks
        t.on_shot(2, true, plain, potted(2, {5}));
        t.on_shot(2, false, plain, wins(2, {8}));
        CHECK(t.of(2).break_and_runs == 1);
    }
    SECTION("a push-out hands the table over") {
        StatsTally t(GameType::eight_ball);
        t.on_shot(1, true, plain, potted(1, {2}));
        Verdict pushed;
        pushed.next_shooter = 2;
        pushed.chooser = 2;
        pushed.choices = {Choice::shoot, Choice::pass_back};
        t.on_shot(1, false, push_out(), pushed);
        t.on_shot(1, false, plain, wins(1, {1, 9})); // passed back
        CHECK(t.of(1).break_and_runs == 0);
        CHECK(t.of(1).pot_attempts == 1);
    }
}

TEST_CASE("a golden break counts as a break-and-run (a real 9-ball game)", "[stats]") {
    Game game = position(
        GameType::nine_ball,
        with_extra({ball_at(0, 0.5, 0.635), ball_at(1, 1.9, 0.635), ball_at(9, 2.1, 0.635)},
                   {2, 3}),
        1, Group::open, true);
    const Verdict v =
        game.apply(plain, hand_made(game, {hit(0, 1), hit(1, 9, 0.15), drop(9, 3, 0.4)}));
    REQUIRE(v.winner == 1);
    REQUIRE(v.reason == WinReason::nine_pocketed);
    StatsTally t(GameType::nine_ball);
    t.on_shot(1, true, plain, v);
    CHECK(t.of(1).break_and_runs == 1);
    CHECK(t.of(1).balls_potted == 1);
    CHECK(t.of(1).longest_run == 1);
    CHECK(t.of(1).pot_attempts == 0);
}

TEST_CASE("the 8 on an 8-ball break comes back and is not counted as potted", "[stats]") {
    Game game = position(
        GameType::eight_ball,
        with_extra({ball_at(0, 0.5, 0.635), ball_at(1, 1.9, 0.635), ball_at(8, 2.1, 0.635)},
                   {2, 9, 10}),
        1, Group::open, true);
    const Verdict v = game.apply(
        plain, hand_made(game, {hit(0, 1), hit(1, 8, 0.15), drop(8, 3, 0.4), drop(2, 1, 0.5)}));
    REQUIRE(v.winner == 0);
    REQUIRE(v.chooser == 1);
    StatsTally t(GameType::eight_ball);
    t.on_shot(1, true, plain, v);
    CHECK(t.of(1).balls_potted == 1); // the 2 only
    CHECK(t.of(1).fouls == 0);
}

TEST_CASE("the longest run is the best visit, across visits", "[stats]") {
    StatsTally t(GameType::eight_ball);
    t.on_shot(1, true, plain, potted(1, {}));
    t.on_shot(2, false, plain, potted(2, {1}));
    t.on_shot(2, false, plain, potted(2, {2}));
    t.on_shot(2, false, plain, potted(2, {})); // 2 balls in this visit
    t.on_shot(1, false, plain, potted(1, {9}));
    t.on_shot(1, false, plain, foul(1)); // the foul ends the visit
    t.on_shot(2, false, plain, potted(2, {3}));
    t.on_shot(2, false, plain, potted(2, {4}));
    t.on_shot(2, false, plain, potted(2, {5, 6}));
    t.on_shot(2, false, plain, potted(2, {})); // 4 balls in this one
    t.on_shot(1, false, plain, potted(1, {10}));
    CHECK(t.of(2).longest_run == 4);
    CHECK(t.of(2).balls_potted == 6);
    CHECK(t.of(1).longest_run == 1); // the 9 and the 10 were separate visits
    CHECK(t.of(1).balls_potted == 2);
    CHECK(t.of(1).racks_played == 0); // the rack is not over
}

TEST_CASE("pot success counts attempts that pot and keep the table", "[stats]") {
    StatsTally t(GameType::eight_ball);
    t.on_shot(1, true, plain, potted(1, {4}));    // a break: not an attempt
    t.on_shot(1, false, plain, potted(1, {5}));   // made
    t.on_shot(1, false, safety(), potted(1, {})); // a safety: not an attempt
    t.on_shot(2, false, plain, potted(2, {}));    // a miss
    Verdict wrong_ball = potted(1, {12});         // potted the opponent's ball: turn passes
    wrong_ball.next_shooter = 2;
    t.on_shot(1, false, plain, wrong_ball);   // tried, not made
    t.on_shot(2, false, plain, foul(2, {6})); // tried, a foul, nothing counted
    t.on_shot(1, false, plain, wins(1, {8})); // made
    const PlayerStats& a = t.of(1);
    CHECK(a.pot_attempts == 3);
    CHECK(a.pots_made == 2);
    CHECK(a.balls_potted == 4); // 4, 5, 12 (legal, if no use) and 8
    REQUIRE(pot_success(a).has_value());
    CHECK(*pot_success(a) == Approx(2.0 / 3));
    const PlayerStats& b = t.of(2);
    CHECK(b.pot_attempts == 2);
    CHECK(b.pots_made == 0);
    CHECK(b.balls_potted == 0);
    CHECK_FALSE(pot_success(PlayerStats{}).has_value());
}

TEST_CASE("fouls are counted and their balls are not potted", "[stats]") {
    StatsTally t(GameType::eight_ball);
    t.on_shot(1, true, plain, foul(1, {3}));
    t.on_shot(2, false, plain, foul(2));
    t.on_shot(1, false, plain, foul(1, {7}));
    Verdict lost; // the 8 early: no foul, but the rack is lost and nothing is potted
    lost.pocketed = {8, 2};
    lost.winner = 1;
    lost.next_shooter = 2;
    t.on_shot(2, false, plain, lost);
    CHECK(t.of(1).fouls == 2);
    CHECK(t.of(2).fouls == 1);
    CHECK(t.of(1).balls_potted == 0);
    CHECK(t.of(2).balls_potted == 0);
    CHECK(t.of(1).racks_won == 1);
    CHECK(t.of(1).shots == 2);
    CHECK(t.of(2).shots == 2);
}

TEST_CASE("snooker: a break is a visit's points, a century one of 100 or more", "[stats]") {
    StatsTally t(GameType::snooker);
    CHECK(t.kind() == StatsKind::snooker);
    t.on_shot(1, true, plain, scores(1, 0, {})); // Ann breaks off, nothing down
    reds_and_blacks(t, 2, 13);                   // Bob: 104
    t.on_shot(2, false, plain, scores(2, 1, {14}));
    t.on_shot(2, false, plain, scores(2, 0, {})); // 105, then a miss
    t.on_shot(1, false, plain, gives_away(1, 4)); // Ann fouls: 4 to Bob
    reds_and_blacks(t, 2, 1);                     // Bob: 8
    t.on_shot(2, false, plain, gives_away(2, 7)); // Bob fouls: 7 to Ann
    const PlayerStats& bob = t.of(2);
    CHECK(bob.highest_break == 105);
    CHECK(bob.centuries == 1); // counted once, when the break passed 100
    CHECK(bob.points == 105 + 4 + 8);
    CHECK(bob.balls_potted == 29); // the blacks too, though they came back
    CHECK(bob.longest_run == 0);   // pool's figures are not kept
    CHECK(bob.fouls == 1);
    CHECK(t.of(1).points == 7);
    CHECK(t.of(1).highest_break == 0);
    CHECK(t.frame_score(1) == 7);
    CHECK(t.frame_score(2) == 117);

    // Ann concedes; the frame's score stays until the next frame's first shot.
    t.on_conceded(2);
    CHECK(bob.racks_won == 1);
    CHECK(t.of(1).racks_played == 1);
    CHECK(t.frame_score(2) == 117);
    t.on_shot(2, true, plain, scores(2, 1, {3})); // the next frame: Bob breaks off and pots
    CHECK(t.frame_score(2) == 1);
    CHECK(t.frame_score(1) == 0);
    CHECK(bob.points == 118);
    CHECK(bob.break_and_runs == 0);
}

TEST_CASE("snooker: the break ends at a re-spotted black, even for its potter", "[stats]") {
    StatsTally t(GameType::snooker);
    reds_and_blacks(t, 1, 8); // 64
    Verdict level = scores(1, 7, {snooker_black});
    level.ball_in_hand = BallInHand::d; // the scores level: the black re-spotted, Ann won the lots
    t.on_shot(1, false, plain, level);
    CHECK(t.of(1).highest_break == 71);
    Verdict black = scores(1, 7, {snooker_black});
    black.winner = 1;
    t.on_shot(1, false, plain, black);
    CHECK(t.of(1).highest_break == 71); // a new visit of 7, not a break of 78
    CHECK(t.frame_score(1) == 78);
    StatsTally u(GameType::snooker);
    u.on_shot(1, false, plain, level);
    u.on_shot(1, false, plain, black);
    CHECK(u.of(1).highest_break == 7);
    CHECK(u.of(1).racks_won == 1);
    CHECK(u.frame_score(1) == 14);
}

TEST_CASE("snooker: the last black potted counts though the frame is lost on points", "[stats]") {
    StatsTally t(GameType::snooker);
    t.on_shot(2, false, plain, scores(2, 40, {snooker_black})); // Bob: 40 ahead
    t.on_shot(2, false, plain, scores(2, 0, {}));
    reds_and_blacks(t, 1, 2); // Ann: 16
    Verdict last = scores(1, 7, {snooker_black});
    last.winner = 2; // Ann pots the last black, 23 to 40: Bob wins the frame
    t.on_shot(1, false, plain, last);
    CHECK(t.of(1).highest_break == 23);
    CHECK(t.of(1).balls_potted == 5);
    CHECK(t.of(1).pots_made == 5);
    CHECK(t.frame_score(1) == 23);
    CHECK(t.of(2).racks_won == 1);
}

TEST_CASE("snooker: the tally follows the referee's score sheet through a frame", "[stats][game]") {
    // Two computers play a frame; after every action the tally's frame score is the
    // referee's, and at the end its highest breaks are the referee's.
    GameRecord header;
    header.setup.game = GameType::snooker;
    header.setup.table = TableSize::snooker;
    header.seed = 5;
    header.computers[0] = Level::hard;
    header.computers[1] = Level::medium;
    Match match = started(header, 9);
    int breaks_seen = 0;
    for (int step = 0; step < 160; ++step) {
        const PendingAction p = match.pending();
        if (p.kind == Pending::over || p.kind == Pending::next_rack)
            break;
        REQUIRE(play_computer_move(match) == MatchError::none);
        const SnookerState& sheet = match.game().snooker();
        CHECK(match.tally().frame_score(1) == sheet.scores[0]);
        CHECK(match.tally().frame_score(2) == sheet.scores[1]);
        for (int player = 1; player <= 2; ++player) {
            // The referee files a break when the visit ends; the tally as it grows.
            const bool at_table = match.game().shooter() == player && match.game().winner() == 0;
            const int referee =
                std::max(sheet.highest_break[player - 1], at_table ? sheet.current_break : 0);
            CHECK(match.tally().of(player).highest_break == referee);
            breaks_seen = std::max(breaks_seen, referee);
        }
    }
    CHECK(breaks_seen > 0);
    const auto replayed = tally_record(match.record());
    REQUIRE(std::holds_alternative<StatsTally>(replayed));
    CHECK(std::get<StatsTally>(replayed).both() == match.tally().both());
}

TEST_CASE("totals add up, the longest run is the longer one", "[stats]") {
    PlayerStats total = some_stats(1);
    total.add(some_stats(2));
    CHECK(total.shots == 23);
    CHECK(total.racks_played == 2);
    CHECK(total.longest_run == 4);
    PlayerStats huge;
    huge.shots = std::numeric_limits<int>::max() - 1;
    huge.add(some_stats(1));
    CHECK(huge.shots == std::numeric_limits<int>::max());
}

TEST_CASE("stats of a whole game played by the computer add up", "[stats][game]") {
    for (const GameType type : {GameType::eight_ball, GameType::nine_ball, GameType::ten_ball}) {
        StatsTally live(type);
        const GameRecord record = computer_game(type, 11, live);
        const auto stats = stats_of_record(record);
        REQUIRE(std::holds_alternative<std::array<PlayerStats, 2>>(stats));
        const auto& s = std::get<std::array<PlayerStats, 2>>(stats);
        INFO(game_type_name(type) << ": " << termpool::stats_summary(record.names, live));
        // Replaying the record hears the same shots as the game did.
        CHECK(s == live.both());
        CHECK(s[0].racks_won + s[1].racks_won == 1);
        CHECK(s[0].racks_played == 1);
        CHECK(s[1].racks_played == 1);
        const int object_balls = type == GameType::nine_ball  ? 9
                                 : type == GameType::ten_ball ? 10
                                                              : 15;
        CHECK(s[0].balls_potted + s[1].balls_potted <= object_balls);
        CHECK(s[0].balls_potted + s[1].balls_potted > 0);
        const auto shots = std::count_if(
            record.actions.begin(), record.actions.end(),
            [](const RecordedAction& a) { return a.kind == RecordedAction::Kind::shot; });
        CHECK(s[0].shots + s[1].shots == shots);
        for (const PlayerStats& p : s) {
            CHECK(p.pots_made <= p.pot_attempts);
            CHECK(p.pot_attempts <= p.shots);
            CHECK(p.fouls <= p.shots);
            CHECK(p.longest_run <= p.balls_potted);
            CHECK(p.break_and_runs <= p.racks_won);
        }
    }
}

TEST_CASE("stats of a record the game refuses name its line", "[stats]") {
    GameRecord record;
    RecordedAction choose;
    choose.kind = RecordedAction::Kind::choose;
    choose.choice = Choice::re_rack;
    choose.line = 7;
    record.actions.push_back(choose);
    const auto stats = stats_of_record(record);
    REQUIRE(std::holds_alternative<RecordError>(stats));
    CHECK(std::get<RecordError>(stats).line == 7);
}

// =============================================================================================
// The totals file

TEST_CASE("the totals file reads back what it wrote, UTF-8 names with spaces included",
          "[stats][file]") {
    StatsStore store;
    const std::string names[2] = {"Bjørn Ås 北京", "CPU (hard)"};
    const PlayerStats game1[2] = {some_stats(1), some_stats(2)};
    termpool::add_game(store, names, GameType::eight_ball, game1);
    const std::string swapped[2] = {"CPU (hard)", "# not a comment"};
    termpool::add_game(store, swapped, GameType::eight_ball, game1);
    REQUIRE(store.players.size() == 3);
    const std::string text = termpool::format_stats(store);
    const auto parsed = termpool::parse_stats(text);
    REQUIRE(std::holds_alternative<StatsStore>(parsed));
    const StatsStore& back = std::get<StatsStore>(parsed);
    REQUIRE(back.players.size() == 3);
    CHECK(back.players[0].name == "Bjørn Ås 北京");
    CHECK(back.players[0].stats == some_stats(1));
    CHECK(back.players[1].name == "CPU (hard)");
    PlayerStats cpu = some_stats(2);
    cpu.add(some_stats(1));
    CHECK(back.players[1].stats == cpu);
    CHECK(back.players[2].name == "# not a comment");
    CHECK(termpool::format_stats(back) == text);
}

TEST_CASE("names that would break a line or the terminal are cleaned", "[stats][file]") {
    CHECK(termpool::stats_name("  Ann\tLee\n ") == "Ann?Lee?");
    CHECK(termpool::stats_name("\x1b[31mred") == "?[31mred");
    CHECK(termpool::stats_name("caf\xc3") == "caf?");
    CHECK(termpool::stats_name("   ") == "?");
    StatsStore store;
    const std::string names[2] = {"Ann\nplayer 9 9 9 9 9 9 9 9 9 Eve", "Bob"};
    const PlayerStats stats[2] = {some_stats(1), some_stats(2)};
    termpool::add_game(store, names, GameType::nine_ball, stats);
    const auto parsed = termpool::parse_stats(termpool::format_stats(store));
    REQUIRE(std::holds_alternative<StatsStore>(parsed));
    CHECK(std::get<StatsStore>(parsed).players.size() == 2);
}

TEST_CASE("a damaged totals file is refused at its line", "[stats][file]") {
    const std::string head = "termpool-stats 2\n";
    const std::string ok = "player 8ball 1 2 30 20 10 12 3 1 5 Ann\n";
    CHECK(parse_error(head + ok) == "");
    CHECK(parse_error("# comment\n\n" + head + ok) == "");
    CHECK(parse_error("") == "1: no 'termpool-stats 2' line: not a stats file, or cut short");
    CHECK(parse_error("player 1 2 3\n") ==
          "1: not a termpool stats file (expected 'termpool-stats 2')");
    CHECK(parse_error("termpool-stats 3\n") ==
          "1: written by a newer termpool (version 3; this one reads 2)");
    CHECK(parse_error(head + ok + "player 8ball 1 2 30 20 10 12 3 1\n") ==
          "3: missing the longest run");
    CHECK(parse_error(head + ok + "player 8ball 1 2 30 20 10 12 3 1 5\n") ==
          "3: missing the player's name");
    CHECK(parse_error(head + "player 9ball 1 2 30 -20 10 12 3 1 5 Bo\n") ==
          "2: pot attempts: '-20' is not a count");
    CHECK(parse_error(head + "player 10ball 1 2 30 20 10 12 3 1 99999999999 Bo\n") ==
          "2: longest run: count 99999999999 is too large");
    CHECK(parse_error(head + "player 8ball-bar 3 2 30 20 10 12 3 1 5 Bo\n") ==
          "2: more racks won (3) than racks played (2)");
    CHECK(parse_error(head + "player 8ball 1 2 30 20 21 22 3 1 5 Bo\n") ==
          "2: more pots made (21) than pot attempts (20)");
    CHECK(parse_error(head + ok + "\nplayer 8ball 0 0 0 0 0 0 0 0 0 Ann\n") ==
          "4: 'Ann' is listed twice for 8ball (first at line 2)");
    CHECK(parse_error(head + ok + "player 9ball 0 0 0 0 0 0 0 0 0 Ann\n") == "");
    CHECK(parse_error(head + "plyer 8ball 0 0 0 0 0 0 0 0 0 Ann\n") ==
          "2: unknown line 'plyer' (expected 'player')");
    CHECK(parse_error(head + "player 0 0 0 0 0 0 0 0 0 Ann\n") ==
          "2: unknown game '0' (expected 8ball, 8ball-bar, 9ball, 10ball, snooker or mixed)");
    CHECK(parse_error(head + "player\n") == "2: missing the game");
    CHECK(parse_error(head + "player 8ball 0 0 0 0 0 0 0 0 0 A\x01n\n") ==
          "2: control characters in the name");
    CHECK(parse_error(head + "player 8ball 0 0 0 0 0 0 0 0 0 caf\xc3\n") ==
          "2: the name is not valid UTF-8");
    CHECK(parse_error(head + "player 8ball 1 2 30 20 10 12 3 1 5 Ann Lee\r\n") == "");
}

TEST_CASE("snooker's totals are frames, points and breaks, and must add up", "[stats][file]") {
    const std::string head = "termpool-stats 2\n";
    // won played shots attempts pots potted fouls points highest-break centuries
    CHECK(parse_error(head + "player snooker 1 2 130 95 60 71 9 240 112 1 Ann\n") == "");
    CHECK(parse_error(head + "player snooker 1 2 130 95 60 71 9 240 112 Ann\n") ==
          "2: centuries: 'Ann' is not a count");
    CHECK(parse_error(head + "player snooker 3 2 130 95 60 71 9 240 112 1 Ann\n") ==
          "2: more frames won (3) than frames played (2)");
    CHECK(parse_error(head + "player snooker 1 2 130 95 60 71 9 90 112 1 Ann\n") ==
          "2: a highest break (112) above all points (90)");
    CHECK(parse_error(head + "player snooker 1 2 130 95 60 71 9 240 112 3 Ann\n") ==
          "2: 3 centuries in 240 points");
    CHECK(parse_error(head + "player snooker 1 2 130 95 60 71 9 240 99 1 Ann\n") ==
          "2: 1 centuries with a highest break of 99");
    CHECK(parse_error(head + "player snooker 1 2 130 95 60 71 9 240 112 0 Ann\n") ==
          "2: 0 centuries with a highest break of 112");
}

TEST_CASE("each game type keeps its own totals, and they read back", "[stats][file]") {
    StatsStore store;
    const std::string names[2] = {"Ann Lee", "Bob"};
    const PlayerStats pool[2] = {some_stats(1), some_stats(2)};
    PlayerStats snooker[2];
    snooker[0].racks_won = snooker[0].racks_played = snooker[1].racks_played = 1;
    snooker[0].shots = 40;
    snooker[0].points = 131;
    snooker[0].highest_break = 104;
    snooker[0].centuries = 1;
    snooker[0].balls_potted = 30;
    snooker[1].points = 12;
    snooker[1].highest_break = 8;
    termpool::add_game(store, names, GameType::eight_ball, pool);
    termpool::add_game(store, names, GameType::snooker, snooker);
    termpool::add_game(store, names, GameType::eight_ball, pool);
    REQUIRE(store.players.size() == 4); // two players, two games each
    const std::string text = termpool::format_stats(store);
    CHECK(text.starts_with("termpool-stats 2\n"));
    CHECK(text.find("\nplayer snooker 1 1 40 0 0 30 0 131 104 1 Ann Lee\n") != std::string::npos);
    const auto parsed = termpool::parse_stats(text);
    REQUIRE(std::holds_alternative<StatsStore>(parsed));
    const StatsStore& back = std::get<StatsStore>(parsed);
    PlayerStats pool_twice = some_stats(1);
    pool_twice.add(some_stats(1));
    REQUIRE(back.find("Ann Lee", GameType::eight_ball));
    CHECK(back.find("Ann Lee", GameType::eight_ball)->stats == pool_twice);
    REQUIRE(back.find("Ann Lee", GameType::snooker));
    CHECK(back.find("Ann Lee", GameType::snooker)->stats == snooker[0]);
    CHECK(back.find("Bob", GameType::snooker)->stats == snooker[1]);
    CHECK_FALSE(back.find("Ann Lee", GameType::nine_ball));
    CHECK(termpool::format_stats(back) == text);
    // Forgetting a player forgets every game of theirs.
    StatsStore fewer = back;
    CHECK(termpool::remove_player(fewer, "Ann Lee"));
    REQUIRE(fewer.players.size() == 2);
    CHECK(fewer.players[0].name == "Bob");
    CHECK(fewer.players[1].name == "Bob");
}

TEST_CASE("a version 1 file still reads: its totals are kept apart as all games mixed",
          "[stats][file]") {
    const std::string v1 = "termpool-stats 1\n"
                           "# won played shots attempts pots potted fouls break-and-runs "
                           "longest-run name\n"
                           "player 3 5 60 52 34 41 6 1 7 Bjørn Ås\n"
                           "player 2 5 55 41 30 37 4 0 6 CPU (hard)\n";
    const auto parsed = termpool::parse_stats(v1);
    REQUIRE(std::holds_alternative<StatsStore>(parsed));
    StatsStore store = std::get<StatsStore>(parsed);
    REQUIRE(store.players.size() == 2);
    CHECK(store.players[0].name == "Bjørn Ås");
    CHECK_FALSE(store.players[0].game.has_value());
    CHECK(store.players[0].stats.racks_played == 5);
    CHECK(store.players[0].stats.longest_run == 7);
    // A game played now goes to its own game's totals, beside the old ones, which are written
    // back as they were.
    const std::string names[2] = {"Bjørn Ås", "CPU (hard)"};
    const PlayerStats stats[2] = {some_stats(1), some_stats(2)};
    termpool::add_game(store, names, GameType::nine_ball, stats);
    const std::string text = termpool::format_stats(store);
    CHECK(text.find("\nplayer mixed 3 5 60 52 34 41 6 1 7 Bjørn Ås\n") != std::string::npos);
    CHECK(text.find("\nplayer 9ball 1 1 11 9 5 6 1 0 3 Bjørn Ås\n") != std::string::npos);
    const auto again = termpool::parse_stats(text);
    REQUIRE(std::holds_alternative<StatsStore>(again));
    CHECK(std::get<StatsStore>(again).players.size() == 4);
    CHECK(std::get<StatsStore>(again).find("Bjørn Ås", std::nullopt)->stats.racks_won == 3);

    // Version 1's own errors keep their words.
    const std::string head = "termpool-stats 1\n";
    CHECK(parse_error(head + "player 3 2 30 20 10 12 3 1 5 Bo\n") ==
          "2: more racks won (3) than racks played (2)");
    CHECK(parse_error(head + "player 1 2 30 20 10 12 3 1 5 Ann\nplayer 0 0 0 0 0 0 0 0 0 Ann\n") ==
          "3: 'Ann' is listed twice (first at line 2)");
}

TEST_CASE("saving a game's figures adds them to the totals", "[stats][file]") {
    const StatsDir dir;
    const std::string path = dir.path() + "/termpool/stats";
    const std::string names[2] = {"Ann Lee", "CPU (hard)"};
    const PlayerStats stats[2] = {some_stats(1), some_stats(2)};
    CHECK(termpool::save_game_stats(path, names, GameType::eight_ball, stats) == "");
    CHECK(termpool::save_game_stats(path, names, GameType::eight_ball, stats) == "");
    const termpool::StatsFile file = termpool::read_stats_file(path);
    REQUIRE(file.state == termpool::StatsFile::State::read);
    REQUIRE(file.store.players.size() == 2);
    PlayerStats twice = some_stats(1);
    twice.add(some_stats(1));
    CHECK(file.store.find("Ann Lee", GameType::eight_ball)->stats == twice);
    // The write went through a temporary file that is gone now.
    CHECK(files_in(dir.path() + "/termpool") == std::vector<std::string>{"stats", "stats.lock"});
}

TEST_CASE("a damaged totals file is reported with its line and kept as .bad", "[stats][file]") {
    const StatsDir dir;
    const std::string path = dir.path() + "/termpool/stats";
    const std::string damaged = "termpool-stats 1\nplayer 1 1 9 9 9 9 0 0 0 Ann\nplayer 1 1 9\n";
    spill(path, damaged);
    const std::string names[2] = {"Ann", "Bob"};
    const PlayerStats stats[2] = {some_stats(1), some_stats(2)};
    const std::string notice = termpool::save_game_stats(path, names, GameType::ten_ball, stats);
    CHECK(notice ==
          path + ":3: missing the pot attempts; kept as " + path + ".bad, new totals started");
    CHECK(slurp(path + ".bad") == damaged);
    const termpool::StatsFile fresh = termpool::read_stats_file(path);
    REQUIRE(fresh.state == termpool::StatsFile::State::read);
    CHECK(fresh.store.find("Ann", GameType::ten_ball)->stats == some_stats(1)); // this game only
    CHECK(fresh.store.players.size() == 2);

    // A second damaged file never replaces the first.
    spill(path, "garbage\n");
    CHECK(termpool::save_game_stats(path, names, GameType::ten_ball, stats)
              .find("kept as " + path + ".bad.1") != std::string::npos);
    CHECK(slurp(path + ".bad") == damaged);
    CHECK(slurp(path + ".bad.1") == "garbage\n");
}

TEST_CASE("a file read is bounded: one too large is refused, not read", "[stats][file]") {
    const StatsDir dir;
    const std::string path = dir.path() + "/big";
    spill(path, std::string(5000, 'x'));
    std::string error;
    CHECK(termpool::read_whole_file(path, error, 5000) == std::string(5000, 'x'));
    CHECK(error.empty());
    CHECK_FALSE(termpool::read_whole_file(path, error, 4999));
    CHECK(error == path + ": 5000 bytes, more than the 4999 allowed");
}

TEST_CASE("a failed write leaves the old totals whole and no temporary file", "[stats][file]") {
    const StatsDir dir;
    const std::string path = dir.path() + "/termpool/stats";
    const std::string names[2] = {"Ann", "Bob"};
    const PlayerStats stats[2] = {some_stats(1), some_stats(2)};
    REQUIRE(termpool::save_game_stats(path, names, GameType::eight_ball, stats) == "");
    const std::string before = slurp(path);
    // A full disk (a file size limit, which stops root too) makes the write fail.
    std::string notice;
    {
        const termpool::test::FileSizeLimit full(0);
        notice = termpool::save_game_stats(path, names, GameType::eight_ball, stats);
    }
    CHECK(notice.starts_with("could not save the statistics: " + path + ".tmp."));
    CHECK(notice.ends_with(": cannot write: " + std::string(std::strerror(EFBIG))));
    CHECK(slurp(path) == before);
    CHECK(files_in(dir.path() + "/termpool") == std::vector<std::string>{"stats", "stats.lock"});
}

// =============================================================================================
// What the player sees

TEST_CASE("the game-over summary fits 36 columns, one column per player", "[stats][tui]") {
    const std::string names[2] = {"北京北京北京北京北京", "A very long name here"};
    BoxFigures f[2];
    f[0].stats.racks_won = 1;
    f[0].stats.racks_played = f[1].stats.racks_played = 1;
    f[0].stats.balls_potted = 7;
    f[0].stats.pot_attempts = 8;
    f[0].stats.pots_made = 6;
    f[0].stats.longest_run = 5;
    f[1].stats.fouls = 2;
    for (const StatsKind kind : {StatsKind::pool, StatsKind::snooker}) {
        const auto lines = lines_of(termpool::stats_summary(kind, names, f));
        REQUIRE(lines.size() >= 7);
        for (const std::string& line : lines) {
            INFO(line);
            CHECK(termpool::display_width(line) <= termpool::stats_summary_columns);
        }
        // Cut names end in an ellipsis, so that two of them side by side read as two.
        CHECK(lines[0].find("北京北京\u2026") != std::string::npos);
        CHECK(lines[0].find("A very lo\u2026") != std::string::npos);
    }
    const auto lines = lines_of(termpool::stats_summary(StatsKind::pool, names, f));
    REQUIRE(lines.size() == 7);
    CHECK(lines[1] == "Racks won               1          0");
    CHECK(lines[3] == "Pot success           75%          -");
    CHECK(lines[4] == "Fouls                   0          2");
    CHECK(lines[5] == "Longest run             5          0");
}

TEST_CASE("the end-of-frame box speaks snooker for snooker and pool for pool", "[stats][tui]") {
    const std::string names[2] = {"Ann", "Bob"};
    StatsTally frame(GameType::snooker);
    frame.on_shot(1, true, plain, scores(1, 0, {}));
    reds_and_blacks(frame, 2, 13); // 104
    frame.on_shot(2, false, plain, scores(2, 0, {}));
    frame.on_shot(1, false, plain, gives_away(1, 4));
    frame.on_conceded(2);
    const std::string snooker = termpool::stats_summary(names, frame);
    INFO(snooker);
    const auto lines = lines_of(snooker);
    REQUIRE(lines.size() == 8);
    CHECK(lines[1] == "Frames won              0          1");
    CHECK(lines[2] == "Frame score             0        108");
    CHECK(lines[3] == "Highest break           0        104");
    CHECK(lines[4] == "Centuries               0          1");
    CHECK(lines[5] == "Balls potted            0         26");
    CHECK(lines[7] == "Fouls                   1          0");
    for (const char* pool_word : {"Rack", "Break-and-runs", "Longest run"})
        CHECK(snooker.find(pool_word) == std::string::npos);

    StatsTally rack(GameType::nine_ball);
    rack.on_shot(1, true, plain, potted(1, {3}));
    rack.on_shot(1, false, plain, wins(1, {9}));
    const std::string pool = termpool::stats_summary(names, rack);
    INFO(pool);
    CHECK(pool.find("Racks won               1          0") != std::string::npos);
    CHECK(pool.find("Break-and-runs          1          0") != std::string::npos);
    for (const char* snooker_word : {"Frame", "break ", "Centuries"})
        CHECK(pool.find(snooker_word) == std::string::npos);
}

TEST_CASE("the stats table lines up names of any width", "[stats][tui]") {
    StatsStore store;
    store.players = {{"Ann", GameType::eight_ball, some_stats(1)},
                     {"北京 Bjørn", GameType::eight_ball, some_stats(2)}};
    const auto lines = lines_of(termpool::cli::stats_table(store));
    REQUIRE(lines.size() >= 4);
    CHECK(lines[0] == "8-ball");
    CHECK(lines[1].starts_with("Player"));
    CHECK(lines[2].starts_with("Ann "));
    CHECK(lines[2].find("5/9") != std::string::npos); // pots made of attempts
    CHECK(lines[2].find("56%") != std::string::npos); // 5/9
    CHECK(lines[3].find("50%") != std::string::npos); // 5/10
    // Every column is right-aligned, so every line ends in the same column.
    CHECK(termpool::display_width(lines[2]) == termpool::display_width(lines[1]));
    CHECK(termpool::display_width(lines[3]) == termpool::display_width(lines[1]));
}

TEST_CASE("the stats table has a section per game type, each with its own figures",
          "[stats][tui]") {
    PlayerStats frames;
    frames.racks_won = frames.racks_played = 2;
    frames.shots = 60;
    frames.pot_attempts = 40;
    frames.pots_made = 30;
    frames.balls_potted = 35;
    frames.points = 201;
    frames.highest_break = 113;
    frames.centuries = 1;
    StatsStore store;
    store.players = {{"Ann", GameType::snooker, frames},
                     {"Ann", std::nullopt, some_stats(2)},
                     {"Ann", GameType::nine_ball, some_stats(1)},
                     {"Bob", GameType::snooker, PlayerStats{}}};
    const std::string table = termpool::cli::stats_table(store);
    INFO(table);
    const auto lines = lines_of(table);
    // 9-ball before snooker (the order of the game types), the version 1 totals last.
    REQUIRE(lines.size() >= 12);
    CHECK(lines[0] == "9-ball");
    CHECK(lines[1] == "Player  Racks  Balls  Pots  Pot success  Fouls  B&R  Run");
    CHECK(lines[2] == "Ann       1/1      6   5/9          56%      1    0    3");
    CHECK(lines[3].empty());
    CHECK(lines[4] == "Snooker");
    CHECK(lines[5] == "Player  Frames  Points  Per frame  High  100s   Pots  Pot success  Fouls");
    CHECK(lines[6] == "Ann        2/2     201      100.5   113     1  30/40          75%      0");
    CHECK(lines[7] == "Bob        0/0       0          -     0     0    0/0            -      0");
    CHECK(lines[8].empty());
    CHECK(lines[9].starts_with("All games before statistics were kept per game"));
    CHECK(lines[10].starts_with("Player  Racks"));
    CHECK(lines[11].starts_with("Ann       0/1"));
    // Each kind of figures is explained once.
    CHECK(table.find("B&R: break-and-runs") != std::string::npos);
    CHECK(table.find("100s: centuries") != std::string::npos);
}

TEST_CASE("termpool stats prints the totals, says when there are none, refuses damage",
          "[stats][cli]") {
    const StatsDir dir;
    const std::string state = dir.path() + "/state";
    const std::string path = state + "/termpool/stats";

    Run r = run_stats(dir, state, "");
    CHECK(r.status == 0);
    CHECK(r.out == "No statistics yet: they are kept in " + path + " after each finished game.\n");

    const std::string names[2] = {"Bjørn Ås", "CPU (hard)"};
    const PlayerStats stats[2] = {some_stats(1), some_stats(2)};
    REQUIRE(termpool::save_game_stats(path, names, GameType::eight_ball, stats) == "");
    PlayerStats frames[2];
    frames[0].racks_won = frames[0].racks_played = frames[1].racks_played = 1;
    frames[0].points = 131;
    frames[0].highest_break = 104;
    frames[0].centuries = 1;
    frames[1].points = 40;
    frames[1].highest_break = 22;
    REQUIRE(termpool::save_game_stats(path, names, GameType::snooker, frames) == "");
    r = run_stats(dir, state, "");
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    INFO(r.out);
    const auto lines = lines_of(r.out);
    REQUIRE(lines.size() >= 9);
    CHECK(lines[0] == "8-ball");
    CHECK(lines[1] == "Player      Racks  Balls  Pots  Pot success  Fouls  B&R  Run");
    CHECK(lines[2] == "Bjørn Ås      1/1      6   5/9          56%      1    0    3");
    CHECK(lines[3] == "CPU (hard)    0/1      6  5/10          50%      1    0    4");
    CHECK(lines[4].empty());
    // Snooker's frames and points are not added to the racks and balls.
    CHECK(lines[5] == "Snooker");
    CHECK(lines[6] ==
          "Player      Frames  Points  Per frame  High  100s  Pots  Pot success  Fouls");
    CHECK(lines[7] ==
          "Bjørn Ås       1/1     131      131.0   104     1   0/0            -      0");
    CHECK(lines[8] ==
          "CPU (hard)     0/1      40       40.0    22     0   0/0            -      0");
    for (const std::string& line : lines)
        CHECK(termpool::display_width(line) <= 80);

    r = run_stats(dir, state, "--reset 'Bjørn Ås'");
    CHECK(r.status == 0);
    const StatsStore left = termpool::read_stats_file(path).store;
    REQUIRE(left.players.size() == 2); // CPU (hard)'s 8-ball and snooker totals
    CHECK(left.players[0].name == "CPU (hard)");
    CHECK(left.players[1].name == "CPU (hard)");
    r = run_stats(dir, state, "--reset Nobody");
    CHECK(r.status == 1);
    CHECK(r.err.find("no statistics for 'Nobody'") != std::string::npos);

    spill(path, "termpool-stats 1\nplayer 1 1 1\n");
    r = run_stats(dir, state, "");
    CHECK(r.status == 2);
    CHECK(r.err.starts_with(path + ":2: missing the pot attempts\n"));
    CHECK(slurp(path) == "termpool-stats 1\nplayer 1 1 1\n"); // left as it is

    r = run_stats(dir, state, "--help");
    CHECK(r.status == 0);
    CHECK(r.out.starts_with("usage: termpool stats [--reset NAME] [--help]\n"));
    r = run_stats(dir, state, "--frobnicate");
    CHECK(r.status == 2);
    CHECK(r.err.find("usage: termpool stats") != std::string::npos);
}
