// The start of a turn as a player meets it, through the real binary in tmux: the names the
// player gave, the aim proposed, what to do next, why a placement is refused, the power kept
// while the pointer only hovers, and the pointer's mark going when keys take over.
#include <catch2/catch.hpp>
#include <string>
#include <termpool/record.hpp>
#include <termpool/table.hpp>
#include <variant>

#include "tmux_session.hpp"
#include "tui/aim.hpp"

using tmux_session::file_text;
using tmux_session::mouse_report;
using tmux_session::ScratchDir;
using tmux_session::Tmux;

namespace {

// The game in tmux at 100x32 with its state in `dir`.
void start_game(const Tmux& t, const std::string& dir, const std::string& args) {
    t.start("env XDG_STATE_HOME=" + dir + " TERM=xterm-256color LANG=C.UTF-8 " +
            tmux_session::termpool_binary() + " " + args + "; sleep 60");
}

// The character at column x, row y of a captured screen (by bytes: fine for ASCII cells).
std::string cell_text(const std::string& screen, int x, int y) {
    std::size_t start = 0;
    for (int row = 0; row < y && start != std::string::npos; ++row) {
        start = screen.find('\n', start);
        if (start != std::string::npos)
            ++start;
    }
    if (start == std::string::npos)
        return "";
    const std::string line = screen.substr(start, screen.find('\n', start) - start);
    // Multi-byte glyphs come before column x on a table row; count display columns instead.
    int col = 0;
    for (std::size_t i = 0; i < line.size();) {
        std::size_t n = 1;
        const unsigned char c = static_cast<unsigned char>(line[i]);
        if (c >= 0xF0)
            n = 4;
        else if (c >= 0xE0)
            n = 3;
        else if (c >= 0xC0)
            n = 2;
        if (col == x)
            return line.substr(i, n);
        i += n;
        ++col;
    }
    return "";
}

} // namespace

TEST_CASE("the status line names the players and says what to do", "[tui][e2e]") {
    ScratchDir dir("termpool-test");
    Tmux t;
    start_game(t, dir.path, "--player1 Ann --player2 Bob --seed 1");
    // The name given on the command line, not "Player 1".
    REQUIRE(t.wait_for_text("Ann breaks: place the cue ball in the kitchen"));
    CHECK(t.screen().find("Player 1") == std::string::npos);

    // Out of the kitchen the placement is refused, with the reason.
    t.repeat("Right", 30);
    t.keys("Enter");
    CHECK(t.wait_for_text("cannot go there: in the kitchen only"));
    // The keys keep the cue ball on the cloth: many more steps still leave it on the table.
    t.repeat("Up", 40);
    t.keys("Enter");
    CHECK(t.wait_for_text("cannot go there: in the kitchen only"));
    // Back in the kitchen it goes, and the line says what comes next.
    t.repeat("Left", 30);
    t.repeat("Down", 20);
    t.keys("Enter");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    CHECK(t.wait_for_text("Ann: aim"));
    CHECK(t.screen().find("Space shoots") != std::string::npos);
}

TEST_CASE("hovering aims but keeps the power; keys take the pointer's mark away", "[tui][e2e]") {
    ScratchDir dir("termpool-test");
    Tmux t;
    start_game(t, dir.path, "--player1 Ann --player2 Bob --seed 1");
    REQUIRE(t.wait_for_text("place the cue ball"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    // The break starts at full power (12.0 m/s); five steps down give 90%, 10.8 m/s.
    REQUIRE(t.wait_for_text("] 12.0 m/s"));
    t.repeat("Down", 5);
    REQUIRE(t.wait_for_text("] 10.8 m/s"));
    // A hover over a far ball aims there, and the power stays.
    const std::string before = t.screen();
    t.keys(mouse_report(35, 86, 6));
    REQUIRE(t.wait_for([&](const std::string& s) { return s != before; }, 5));
    CHECK(t.wait_for_text("] 10.8 m/s", 1));
    CHECK(cell_text(t.screen(), 86, 6) == "+");
    // The keys turn the aim: the mark of the pointer is gone.
    t.keys("Left");
    CHECK(t.wait_for([](const std::string& s) { return cell_text(s, 86, 6) != "+"; }, 5));
    // Dragging sets the power from the pointer's distance (near the cue ball: little).
    t.keys(mouse_report(0, 30, 13));
    CHECK(t.wait_for(
        [](const std::string& s) {
            return s.find("] 12.0 m/s") == std::string::npos &&
                   s.find("] 10.8 m/s") == std::string::npos;
        },
        5));
}

TEST_CASE("9-ball: Space at the start of each turn never hits a wrong ball first", "[tui][e2e]") {
    ScratchDir dir("termpool-test");
    const std::string save = dir.path + "/termpool/game.save";
    Tmux t;
    start_game(t, dir.path, "--game 9ball --player1 Ann --player2 Bob --seed 2");
    REQUIRE(t.wait_for_text("place the cue ball"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    t.repeat("Up", 40);
    // The push-out is offered in words after the break.
    auto shots_saved = [&] {
        const std::string text = file_text(save);
        int n = 0;
        for (std::size_t at = text.find("\nshot "); at != std::string::npos;
             at = text.find("\nshot ", at + 1))
            ++n;
        return n;
    };
    constexpr int shots = 11;
    bool push_out_hint = false;
    for (int shot = 0; shot < shots; ++shot) {
        // Wait for a turn to start: aiming, or a ball in hand to place where proposed.
        CAPTURE(shot);
        const bool started = t.wait_for(
            [](const std::string& s) {
                return s.find("[ shoot ]") != std::string::npos ||
                       s.find("place the cue ball") != std::string::npos ||
                       s.find("ball in hand") != std::string::npos ||
                       s.find("rematch") != std::string::npos;
            },
            20);
        CAPTURE(t.screen());
        REQUIRE(started);
        if (t.screen().find("rematch") != std::string::npos)
            break;
        if (t.screen().find("[ shoot ]") == std::string::npos) {
            t.keys("Enter");
            REQUIRE(t.wait_for_text("[ shoot ]"));
        }
        if (shot == 1) {
            push_out_hint = t.screen().find("u declares a push-out") != std::string::npos;
            // The break was at full power; the shots after it at the player's own (30%).
            CHECK(t.screen().find("] 2.3 m/s") != std::string::npos);
        }
        t.keys("Space");
        t.keys("x");
        REQUIRE(t.wait_for([&](const std::string&) { return shots_saved() == shot + 1; }, 20));
    }
    CHECK(push_out_hint);
    t.keys("q");
    t.keys("y");

    // Replayed: every shot after the break went where the game proposed (standard, the
    // default: full at the easiest legal ball), and none that had a straight line to it hit a
    // wrong ball first or no ball at all.
    auto parsed = termpool::parse_record(file_text(save));
    REQUIRE(std::holds_alternative<termpool::GameRecord>(parsed));
    const termpool::GameRecord& record = std::get<termpool::GameRecord>(parsed);
    termpool::Game game(record.setup.game, termpool::make_table(record.setup), record.setup.physics,
                        record.breaker, record.seed);
    int judged = 0, straight = 0;
    for (const termpool::RecordedAction& a : record.actions) {
        if (a.kind == termpool::RecordedAction::Kind::place) {
            REQUIRE(game.place_cue_ball(a.place));
            continue;
        }
        if (a.kind == termpool::RecordedAction::Kind::choose) {
            REQUIRE(game.choose(a.choice));
            continue;
        }
        const bool is_break = game.is_break();
        termpool::Vec2 cue;
        for (const termpool::Ball& b : game.balls())
            if (b.id == 0)
                cue = b.position;
        const auto ranked =
            termpool::tui::rank_openings(game.table(), game.balls(), game.params().ball_radius, cue,
                                         game.legal_targets(), record.assist);
        const termpool::Verdict v = game.play(a.strike, a.call);
        if (is_break || ranked.empty())
            continue;
        ++judged;
        CAPTURE(judged, a.strike.angle_deg, ranked[0].ball, ranked[0].aim_deg);
        CHECK(a.strike.angle_deg == Approx(ranked[0].aim_deg).margin(1e-9));
        if (ranked[0].line == termpool::tui::TargetLine::straight) {
            ++straight;
            CHECK(v.foul != termpool::Foul::wrong_ball_first);
            CHECK(v.foul != termpool::Foul::no_contact);
        }
    }
    CHECK(judged >= 5);
    CHECK(straight >= 3);
}
