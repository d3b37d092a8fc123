// Snooker played in the terminal: the panel's score sheet (the scores, the break, the highest
// breaks, the ball on, the points left, the frames of a best-of match) at every size and in every
// tier of colour and glyphs, the nomination keys, the snooker choices in a referee's words, the
// --best-of option, and the real binary's frame against the computer in tmux: the cue ball placed
// in the D, the break, and the score panel.
#include <catch2/catch.hpp>
#include <fstream>
#include <limits>
#include <optional>
#include <regex>
#include <string>
#include <termpool/match.hpp>
#include <termpool/rack.hpp>
#include <termpool/record.hpp>
#include <termpool/setup.hpp>
#include <termpool/snooker_layout.hpp>
#include <termpool/table_physics.hpp>
#include <variant>
#include <vector>

#include "match_helpers.hpp"
#include "player/options.hpp"
#include "tmux_session.hpp"
#include "tui/aim_state.hpp"
#include "tui/messages.hpp"
#include "tui/nomination.hpp"
#include "tui/snooker_panel.hpp"
#include "tui/view.hpp"
#include <termpool/text_width.hpp>

using namespace termpool;
using namespace termpool::tui;

namespace {

const PhysicsParams params = physics_for_table(TableSize::snooker);
const Table table = make_table(TableSize::snooker, params.ball_radius);

const Capabilities tiers[] = {{256, true}, {8, true}, {0, true}, {256, false}, {0, false}};
const std::pair<int, int> sizes[] = {{80, 24}, {100, 32}, {120, 40}, {200, 60}, {120, 24}};

// A frame in a best of 5 (Ann leads 1-0 in frames): Ann on 42 with a break of 12 going and a
// high break of 23, Bob on 17 with 9; the reds still on, 67 points left.
View frame_view() {
    View v;
    v.table = &table;
    v.balls = make_rack(table, params, RackType::snooker, 3);
    v.ball_radius = params.ball_radius;
    v.game = GameType::snooker;
    v.names[0] = "Ann";
    v.names[1] = "Bob";
    v.shooter = 1;
    v.scores[0] = 42;
    v.scores[1] = 17;
    v.current_break = 12;
    v.highest_break[0] = 23;
    v.highest_break[1] = 9;
    v.ball_on = BallOn::red;
    v.points_remaining = 67;
    v.best_of = 5;
    v.racks_won[0] = 1;
    v.message = "Ann scores 1 and plays on";
    return v;
}

// The panel's rows (its own columns only).
std::vector<std::string> panel_rows(const Grid& g, const Layout& l) {
    std::vector<std::string> rows;
    for (int y = l.panel_y; y < l.panel_y + l.panel_height; ++y) {
        std::string row;
        for (int x = l.panel_x; x < l.panel_x + l.panel_width && x < g.width; ++x)
            row += g.at(x, y).glyph;
        rows.push_back(row);
    }
    return rows;
}

bool has(const std::vector<std::string>& rows, const std::string& text) {
    for (const std::string& r : rows)
        if (r.find(text) != std::string::npos)
            return true;
    return false;
}

} // namespace

TEST_CASE("the snooker panel shows the scores, the break, the ball on and the frames",
          "[tui][snooker][snooker-play]") {
    const View v = frame_view();
    for (const Capabilities& caps : tiers)
        for (const auto& [w, h] : sizes) {
            CAPTURE(caps.colours, caps.utf8, w, h);
            const Layout l = make_layout(table, w, h);
            REQUIRE(l.fits);
            const auto rows = panel_rows(render(v, l, caps, w, h), l);
            CHECK(has(rows, "Frames 1-0 (best of 5)"));
            CHECK(has(rows, "Ann"));
            CHECK(has(rows, " 42"));
            CHECK(has(rows, " 17"));
            CHECK(has(rows, "break 12"));
            CHECK(has(rows, "on red"));
            CHECK(has(rows, "67 left"));
            // The pool panel's words have no place here.
            CHECK_FALSE(has(rows, "open table"));
            CHECK_FALSE(has(rows, "race to"));
            // Nothing of the panel spills past the grid's width, and each line fits it.
            for (const std::string& r : rows)
                CHECK(display_width(r) <= l.panel_width);
        }
}

TEST_CASE("the snooker panel lines up the scores and shows the high breaks where there is room",
          "[tui][snooker][snooker-play]") {
    View v = frame_view();
    v.scores[0] = 102;
    v.scores[1] = 7;
    const Layout l = make_layout(table, 80, 24);
    const auto rows = panel_rows(render(v, l, {0, false}, 80, 24), l);
    std::size_t a = std::string::npos, b = std::string::npos;
    for (const std::string& r : rows) {
        if (r.find("Ann") != std::string::npos)
            a = r.find("102");
        if (r.find("Bob") != std::string::npos)
            b = r.find("  7");
    }
    REQUIRE(a != std::string::npos);
    REQUIRE(b != std::string::npos);
    CHECK(a == b); // the units line up: "102" over "  7"
    CHECK(has(rows, "high break 23"));
    // At 120x24 the panel is beside the table, each player's high break under the name.
    const Layout side = make_layout(table, 120, 24);
    REQUIRE_FALSE(side.panel_below);
    const auto side_rows = panel_rows(render(v, side, {0, false}, 120, 24), side);
    CHECK(has(side_rows, "high break 23"));
    CHECK(has(side_rows, "high break 9"));
}

TEST_CASE("the ball on in the panel's words", "[tui][snooker][snooker-play]") {
    View v = frame_view();
    CHECK(ball_on_text(v) == "on red");
    v.ball_on = BallOn::colour;
    CHECK(ball_on_text(v) == "on a colour");
    v.nominated = snooker_blue;
    CHECK(ball_on_text(v) == "on a colour: blue");
    v.nomination_chosen = true;
    CHECK(ball_on_text(v) == "nominated blue");
    v.ball_on = BallOn::in_order;
    v.lowest_colour = snooker_yellow;
    CHECK(ball_on_text(v) == "on yellow");
    v.free_ball = true;
    v.nominated = snooker_pink;
    CHECK(ball_on_text(v) == "free ball: pink");
    v.nominated = 0;
    CHECK(ball_on_text(v) == "free ball");
    v = frame_view();
    CHECK(snooker_status(v) == "break 12  on red  67 left");
    v.current_break = 0;
    CHECK(snooker_status(v) == "on red  67 left");
    // A single frame says nothing of frames.
    v.best_of = 0;
    CHECK(frames_text(v).empty());
    const Layout l = make_layout(table, 100, 32);
    const auto rows = panel_rows(render(v, l, {256, true}, 100, 32), l);
    CHECK_FALSE(has(rows, "Frames"));
    CHECK(has(rows, "snooker"));
}

TEST_CASE("the nomination keys name a colour by its value, the aimed one proposed",
          "[tui][snooker][snooker-play]") {
    std::vector<Ball> balls = make_rack(table, params, RackType::snooker, 3);
    for (Ball& b : balls)
        if (b.id == 1)
            b.state = MotionState::pocketed; // the red just potted
    SnookerState state;
    state.ball_on = BallOn::colour;
    state.scores[0] = 1;
    state.current_break = 1;
    const Game g = Game::from_snooker_position(table, params, balls, 1, state);
    REQUIRE(g.nomination_owed());
    AimState aim;
    aim.preview_ball = snooker_blue;
    propose_nomination(g, aim);
    CHECK(aim.nominated == snooker_blue);
    CHECK_FALSE(aim.nomination_chosen);
    // Not named: the referee takes the ball hit first (the aimed one).
    CHECK(nomination_call(g, aim).ball == 0);
    // 6 names the pink, whatever is aimed at.
    const auto said = nomination_key(g, aim, "6", "Ann");
    REQUIRE(said);
    CHECK(*said == "Ann nominates pink");
    CHECK(aim.nominated == snooker_pink);
    CHECK(aim.nomination_chosen);
    aim.preview_ball = snooker_black;
    propose_nomination(g, aim);
    CHECK(aim.nominated == snooker_pink);
    CHECK(nomination_call(g, aim).ball == snooker_pink);
    // Each value names its colour.
    for (int value = 2; value <= 7; ++value) {
        AimState a;
        REQUIRE(nomination_key(g, a, std::to_string(value), "Ann"));
        CHECK(a.nominated == snooker_yellow + value - 2);
        CHECK(snooker_value(a.nominated) == value);
    }
    // The same key again goes back to the aimed ball.
    REQUIRE(nomination_key(g, aim, "6", "Ann"));
    CHECK_FALSE(aim.nomination_chosen);
    CHECK(aim.nominated == snooker_black);
    // 1, 8, 9 and 0 are no colour; other keys are not the nomination's.
    for (const char* key : {"1", "8", "9", "0"}) {
        AimState a;
        const auto m = nomination_key(g, a, key, "Ann");
        REQUIRE(m);
        CHECK(m->find("2 yellow") != std::string::npos);
        CHECK(a.nominated == 0);
    }
    CHECK_FALSE(nomination_key(g, aim, "w", "Ann"));
    // Aiming at a red proposes nothing: the referee takes the colour hit first.
    AimState at_red;
    at_red.preview_ball = 5;
    propose_nomination(g, at_red);
    CHECK(at_red.nominated == 0);
}

TEST_CASE("no nomination on the reds; a free ball may be any ball not on",
          "[tui][snooker][snooker-play]") {
    const std::vector<Ball> balls = make_rack(table, params, RackType::snooker, 3);
    SnookerState state;
    const Game on_red = Game::from_snooker_position(table, params, balls, 1, state);
    AimState aim;
    aim.preview_ball = snooker_blue;
    propose_nomination(on_red, aim);
    CHECK(aim.nominated == 0);
    const auto said = nomination_key(on_red, aim, "5", "Ann");
    REQUIRE(said);
    CHECK(said->find("No nomination now") == 0);
    CHECK(aim.nominated == 0);
    CHECK(nomination_call(on_red, aim).ball == 0);

    state.free_ball = true;
    const Game free = Game::from_snooker_position(table, params, balls, 1, state);
    REQUIRE(free.nomination_owed());
    AimState f;
    f.preview_ball = 3; // a red is on: playing it is no free ball
    propose_nomination(free, f);
    CHECK(f.nominated == 0);
    f.preview_ball = snooker_green;
    propose_nomination(free, f);
    CHECK(f.nominated == snooker_green);
    const auto named = nomination_key(free, f, "7", "Bob");
    REQUIRE(named);
    CHECK(*named == "Bob nominates the free ball: black");
    CHECK(nomination_call(free, f).ball == snooker_black);
}

TEST_CASE("snooker's choices in a referee's words", "[tui][snooker][snooker-play]") {
    CHECK(choice_words(Choice::play_on, GameType::snooker, false) == "play on from here");
    CHECK(choice_words(Choice::play_on, GameType::snooker, true) == "play on, with a free ball");
    CHECK(choice_words(Choice::offender_plays, GameType::snooker, false) ==
          "put the offender back in");
    CHECK(choice_words(Choice::replace_and_replay, GameType::snooker, false).find("replace") == 0);
    // Pool keeps its own.
    CHECK(choice_words(Choice::play_on, GameType::eight_ball, false) == "play on");
    // After an in-off both choices start with the cue ball placed in the D.
    CHECK(choice_words(Choice::play_on, GameType::snooker, false, BallInHand::d) ==
          "play on, the cue ball in hand in the D");
    CHECK(choice_words(Choice::offender_plays, GameType::snooker, false, BallInHand::d) ==
          "put the offender back in, the cue ball in the D");
    CHECK(ball_in_hand_words(BallInHand::d) == "in the D");
    CHECK(snooker_ball_name(snooker_brown) == "brown");
    CHECK(snooker_ball_name(7) == "red");
}

TEST_CASE("--best-of N is a race to more than half the frames", "[tui][snooker][snooker-play]") {
    std::string error;
    const auto o = parse_game_options({"--game", "snooker", "--best-of", "5"}, error);
    REQUIRE(o);
    CHECK(o->race_to == 3);
    CHECK(o->setup.game == GameType::snooker);
    CHECK(table_played(o->setup) == TableSize::snooker);
    for (const char* bad : {"4", "0", "199", "x", "-3"}) {
        CAPTURE(bad);
        CHECK_FALSE(parse_game_options({"--best-of", bad}, error));
        CHECK(error.find("--best-of") == 0);
    }
    CHECK(parse_best_of("1") == 1);
    CHECK(parse_best_of("197") == 197);
}

TEST_CASE("a frame against the computer in tmux: in the D, the break, the score panel",
          "[tui][e2e][snooker][snooker-play]") {
    using namespace tmux_session;
    for (const auto& [w, h] : {std::pair{100, 32}, {80, 24}}) {
        CAPTURE(w, h);
        const ScratchDir scratch("termpool-snooker-play");
        Tmux t;
        t.start("env XDG_STATE_HOME=" + scratch.path + " XDG_CONFIG_HOME=" + scratch.path +
                    " TERM=xterm-256color LANG=C.UTF-8 " + termpool_binary() +
                    " --game snooker --best-of 3 --player1 Ann --vs-computer easy --seed 3",
                w, h);
        // At 80 columns the panel wraps the line before "the D".
        const bool placing = t.wait_for_text("Ann breaks off: place the cue ball");
        CAPTURE(t.screen());
        REQUIRE(placing);
        CHECK(t.wait_for_text("Frames 0-0 (best of 3)"));
        CHECK(t.wait_for_text("on red"));
        CHECK(t.wait_for_text("147 left"));
        // The keys keep the cue ball in the D: many steps left and up still leave it there.
        t.repeat("Left", 30);
        t.repeat("Up", 20);
        t.keys("Enter");
        REQUIRE(t.wait_for_text("Left/Right"));
        CHECK(t.screen().find("cannot go there") == std::string::npos);
        // The break-off opens soft (a pool break's full 12 m/s would scatter the pack), and
        // Space plays it as proposed.
        CHECK(t.wait_for([](const std::string& s) {
            return std::regex_search(s, std::regex("\\] [2-4]\\.[0-9] m/s"));
        }));
        CHECK(t.screen().find("12.0 m/s") == std::string::npos);
        t.keys("Space");
        t.keys("x"); // the rest of the shot at once: its end is what is checked
        // The shot rolls, then the panel has the score sheet of the frame.
        REQUIRE(t.wait_for([](const std::string& s) {
            return s.find("Ann shoots") == std::string::npos &&
                   s.find("Left/Right") == std::string::npos;
        }));
        CHECK(t.wait_for_text("left"));
        CHECK(t.wait_for_text("Frames 0-0 (best of 3)"));
        const std::string s = t.screen();
        CHECK(s.find("Ann") != std::string::npos);
        CHECK(s.find("CPU (easy)") != std::string::npos);
        t.keys("q");
        CHECK(t.wait_for_text("Quit the game?"));
        t.keys("y");
    }
}

namespace {

// A frame of snooker in tmux between Ann and Bob (seed 3, and `args`), Ann at the aim once the
// cue ball is placed in the D.
void start_frame(tmux_session::Tmux& t, const tmux_session::ScratchDir& scratch,
                 const std::string& args) {
    t.start("env XDG_STATE_HOME=" + scratch.path + " XDG_CONFIG_HOME=" + scratch.path +
                " TERM=xterm-256color LANG=C.UTF-8 " + tmux_session::termpool_binary() +
                " --game snooker " + args + " --player1 Ann --player2 Bob --seed 3",
            100, 32);
    REQUIRE(t.wait_for_text("Ann breaks off: place the cue ball in the D"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("Left/Right"));
}

} // namespace

TEST_CASE("C concedes the frame in tmux once y confirms it", "[tui][e2e][snooker][snooker-play]") {
    using namespace tmux_session;
    const ScratchDir scratch("termpool-snooker-concede");
    Tmux t;
    start_frame(t, scratch, "--best-of 3");
    // Anything but y keeps the frame going.
    t.keys("C");
    REQUIRE(t.wait_for_text("Ann: concede the frame?  y / n"));
    t.keys("n");
    REQUIRE(t.wait_for(
        [](const std::string& s) { return s.find("concede the frame?") == std::string::npos; }));
    CHECK(t.screen().find("concedes") == std::string::npos);
    t.keys("C");
    REQUIRE(t.wait_for_text("Ann: concede the frame?  y / n"));
    t.keys("y");
    CHECK(t.wait_for_text("Ann concedes the frame"));
    CHECK(t.wait_for_text("Best of 3 frames: Ann 0, Bob 1"));
    // The next frame, Bob to break from the D; the panel has the frame score.
    t.keys("Enter");
    CHECK(t.wait_for_text("Frame 2: Bob breaks off: place the cue ball in the D"));
    CHECK(t.wait_for_text("Frames 0-1 (best of 3)"));
}

TEST_CASE("a single frame's end offers the next frame, in snooker's words",
          "[tui][e2e][snooker][snooker-play]") {
    using namespace tmux_session;
    const ScratchDir scratch("termpool-snooker-next-frame");
    Tmux t;
    start_frame(t, scratch, "--race 1");
    t.keys("C");
    REQUIRE(t.wait_for_text("Ann: concede the frame?  y / n"));
    t.keys("y");
    CHECK(t.wait_for_text("next frame (the loser breaks off)"));
    const std::string box = t.screen();
    CHECK(box.find("rematch") == std::string::npos);
    // The figures are a frame's: frames, points and breaks, not pool's racks and runs.
    for (const char* row : {"Frames won", "Frame score", "Highest break", "Centuries"})
        CHECK(box.find(row) != std::string::npos);
    for (const char* row : {"Racks won", "Break-and-runs", "Longest run"})
        CHECK(box.find(row) == std::string::npos);
}

namespace {

// A snooker frame between two pro computers up to the first shot that owes a nomination (a red
// just potted), saved with people in both seats (Ann and Bob); empty if none came.
std::string frame_owing_a_nomination() {
    GameRecord header;
    header.setup.game = GameType::snooker;
    header.setup.table = TableSize::snooker;
    header.seed = 11;
    header.names[0] = "Ann";
    header.names[1] = "Bob";
    header.computers[0] = header.computers[1] = Level::easy;
    Match match = test::started(header, 5);
    for (int step = 0; step < 400; ++step) {
        const PendingAction p = match.pending();
        if (p.kind == Pending::shoot && match.game().nomination_owed() &&
            !match.game().snooker().free_ball) {
            match.seat_computer(1, std::nullopt);
            match.seat_computer(2, std::nullopt);
            return format_record(match.record());
        }
        if (p.kind == Pending::over || p.kind == Pending::next_rack)
            return "";
        REQUIRE(test::play_computer_move(match) == MatchError::none);
    }
    return "";
}

} // namespace

TEST_CASE("after a red the keys 2-7 nominate a colour in tmux, and the shot calls it",
          "[tui][e2e][snooker][snooker-play]") {
    using namespace tmux_session;
    const std::string saved = frame_owing_a_nomination();
    REQUIRE_FALSE(saved.empty());
    const ScratchDir scratch("termpool-snooker-nominate");
    const std::string file = scratch.path + "/frame.save";
    std::ofstream(file) << saved;
    Tmux t;
    t.start("env XDG_STATE_HOME=" + scratch.path + " XDG_CONFIG_HOME=" + scratch.path +
                " TERM=xterm-256color LANG=C.UTF-8 " + termpool_binary() + " --resume " + file +
                "; sleep 60",
            100, 32);
    REQUIRE(t.wait_for_text("Game resumed"));
    CHECK(t.wait_for_text("2-7 nominates a colour"));
    // The aimed colour is proposed until one is named.
    CHECK(t.wait_for_text("on a colour"));
    t.keys("7");
    CHECK(t.wait_for_text("nominates black"));
    CHECK(t.wait_for_text("nominated black"));
    // The same key again: back to the aimed ball; then the pink.
    t.keys("7");
    CHECK(t.wait_for_text("Nomination: the ball aimed at"));
    t.keys("6");
    CHECK(t.wait_for_text("nominated pink"));
    // Naming the pink turned the cue to it: the shot meets the pink first.
    CHECK(t.wait_for_text("the cue turns to it"));
    t.keys("Space");
    t.keys("x"); // the shot is saved once it has rolled: at once
    // The shot is saved with its nomination: the pink, ball 20, no pocket.
    CHECK(t.wait_for([&](const std::string&) {
        return file_text(file).find(" call 20 0") != std::string::npos;
    }));
    CHECK(t.wait_for([](const std::string& s) { return s.find("shoots") == std::string::npos; }));
    CHECK(t.screen().find("wrong ball first") == std::string::npos);
    // The saved game played again: the nominated pink is the first ball the cue ball met.
    const auto record = parse_record(file_text(file));
    REQUIRE(std::holds_alternative<GameRecord>(record));
    std::optional<PlayedShot> last;
    const auto replayed =
        Match::replay(std::get<GameRecord>(record), std::numeric_limits<std::size_t>::max(),
                      [&](const PlayedShot& shot) { last = shot; });
    REQUIRE(std::holds_alternative<Match>(replayed));
    REQUIRE(last);
    CHECK(last->call.call.ball == snooker_pink);
    CHECK(last->verdict.first_contact == snooker_pink);
}
