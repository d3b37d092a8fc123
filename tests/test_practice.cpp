// Practice: no referee, balls picked up and put down where they touch nothing, the last shot
// taken again bit for bit, and a pocketed cue ball back on the head spot.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstring>
#include <termpool/practice.hpp>
#include <termpool/rules.hpp>

#include "tmux_session.hpp"

using namespace termpool;

namespace {

bool same_bits(const std::vector<Ball>& a, const std::vector<Ball>& b) {
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].id != b[i].id || a[i].state != b[i].state ||
            std::memcmp(&a[i].position, &b[i].position, sizeof(Vec2)) != 0)
            return false;
    return true;
}

const Ball& ball(const PracticeTable& p, int id) {
    for (const Ball& b : p.balls())
        if (b.id == id)
            return b;
    FAIL("no ball " << id);
    return p.balls().front();
}

} // namespace

TEST_CASE("practice: balls go down only where they touch nothing", "[practice]") {
    const Table table = make_table(TableSize::nine_foot);
    const PhysicsParams params;
    PracticeTable p(table, params, RackType::eight_ball, 7);
    const double R = params.ball_radius;
    CHECK(p.is_break());
    CHECK_FALSE(p.can_retake());
    // On top of the 8 (in the rack), off the cloth: refused, nothing moves.
    const Vec2 eight = ball(p, 8).position;
    const std::vector<Ball> before = p.balls();
    CHECK_FALSE(p.put(5, eight + Vec2{R, 0}));
    CHECK_FALSE(p.put(5, {-0.1, 0.5}));
    CHECK_FALSE(p.put(5, {table.length - R / 2, 0.5}));
    CHECK_FALSE(p.put(99, {0.5, 0.5}));
    CHECK(same_bits(p.balls(), before));
    // A free spot takes it, at rest; a ball may go where it already is.
    REQUIRE(p.put(5, {0.5, 0.3}));
    CHECK(ball(p, 5).position.x == 0.5);
    CHECK(ball(p, 5).state == MotionState::stationary);
    CHECK(p.can_put(8, eight));
    // Right beside another ball (just touching is allowed, overlapping is not).
    CHECK(p.can_put(6, Vec2{0.5 + 2 * R, 0.3}));
    CHECK_FALSE(p.can_put(6, Vec2{0.5 + 1.9 * R, 0.3}));
}

TEST_CASE("practice: the last shot is taken again from the same balls", "[practice]") {
    const Table table = make_table(TableSize::nine_foot);
    const PhysicsParams params;
    PracticeTable p(table, params, RackType::nine_ball, 3);
    const std::vector<Ball> rack = p.balls();
    const ShotResult first = p.shoot({9.0, 0.5, 0.1, -0.1});
    CHECK_FALSE(p.is_break());
    CHECK(p.can_retake());
    CHECK_FALSE(same_bits(p.balls(), rack));
    const std::vector<Ball> after = p.balls();
    REQUIRE(p.retake());
    CHECK(p.is_break());
    CHECK(same_bits(p.balls(), rack));
    CHECK_FALSE(p.retake()); // once: the position before that is gone
    // The same strike again gives the same table, bit for bit.
    const ShotResult again = p.shoot({9.0, 0.5, 0.1, -0.1});
    CHECK(again.events == first.events);
    CHECK(same_bits(p.balls(), after));
    p.rerack(4);
    CHECK(p.is_break());
    CHECK_FALSE(p.can_retake());
}

TEST_CASE("practice: a pocketed cue ball comes back to the head spot", "[practice]") {
    const Table table = make_table(TableSize::nine_foot);
    const PhysicsParams params;
    PracticeTable p(table, params, RackType::nine_ball, 3);
    // Alone near corner pocket 1, straight in.
    for (const Ball& b : std::vector<Ball>(p.balls()))
        if (b.id != 0)
            REQUIRE(p.put(b.id, {table.length - 0.2 - 0.06 * b.id, table.width - 0.1}));
    REQUIRE(p.put(0, {0.3, 0.3}));
    const ShotResult scratch = p.shoot({2.0, 225, 0, 0});
    REQUIRE(std::any_of(scratch.events.begin(), scratch.events.end(),
                        [](const Event& e) { return e.kind == EventKind::pocket && e.ball == 0; }));
    CHECK(ball(p, 0).state != MotionState::pocketed);
    CHECK(ball(p, 0).position.x == table.head_spot().x);
    CHECK(ball(p, 0).position.y == table.head_spot().y);
    // With the head spot covered it goes to the free spot beside it on the long string.
    REQUIRE(p.put(0, {0.3, 0.3}));
    REQUIRE(p.put(1, table.head_spot()));
    const Vec2 spot = p.free_spot_near(0, table.head_spot());
    CHECK(spot.y == table.head_spot().y);
    CHECK(p.can_put(0, spot));
    CHECK(std::abs(spot.x - table.head_spot().x) >= 2 * params.ball_radius);
}

TEST_CASE("termpool practice in tmux: one name, shoot, take it again, move a ball",
          "[practice][tui][e2e]") {
    tmux_session::ScratchDir dir("termpool-test");
    tmux_session::Tmux t;
    t.start(tmux_session::game_command(dir, "practice --seed 3"));
    REQUIRE(t.wait_for_text("Name of player 1"));
    t.keys("-l Zed");
    t.keys("Enter");
    // One player: no second name is asked for, and the table is ready to shoot.
    REQUIRE(t.wait_for_text("[ shoot ]"));
    CHECK(t.screen().find("Name of player 2") == std::string::npos);
    CHECK(t.screen().find("no referee") != std::string::npos);
    const auto table_rows = [](const std::string& s) { return s.substr(0, s.find("power [")); };
    const std::string rack = table_rows(t.screen());
    CHECK(t.screen().find("12.0 m/s") != std::string::npos); // the break's full bar
    t.keys("Space");
    t.keys("x");
    REQUIRE(t.wait_for_text("r takes the shot again"));
    CHECK(t.screen().find("calls the") == std::string::npos); // no referee, no called pockets
    CHECK(table_rows(t.screen()) != rack);
    t.keys("r");
    REQUIRE(t.wait_for_text("The balls are back"));
    // The same balls and the same aim as before the shot, and the break's full bar again.
    CHECK(t.wait_for([&](const std::string& s) { return table_rows(s) == rack; }, 3));
    CHECK(t.wait_for_text("12.0 m/s"));
    // Move the cue ball: m, Tab picks it, three cells left, Enter puts it down.
    t.keys("m");
    t.keys("Tab");
    REQUIRE(t.wait_for_text("Moving the cue ball"));
    t.keys("Left Left Left Enter");
    REQUIRE(t.wait_for_text("Put down the cue ball"));
    t.keys("Escape");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    CHECK(table_rows(t.screen()) != rack);
    // Practice writes no save.
    t.keys("q");
    t.keys("y");
    // Once it has exited, nothing is saved.
    CHECK(tmux_session::exit_status(dir.status_file()) == "0");
    CHECK(tmux_session::file_text(dir.save()).empty());
}

TEST_CASE("practice with a seed racks what a game with that seed breaks", "[practice]") {
    const Table table = make_table(TableSize::nine_foot);
    const PhysicsParams params;
    for (const std::uint64_t seed : {1u, 9u, 12345u}) {
        const PracticeTable p(table, params, RackType::nine_ball, seed);
        const Game g(GameType::nine_ball, table, params, 1, seed);
        CHECK(same_bits(p.balls(), g.balls()));
    }
}

TEST_CASE("practice refuses the options of a game between two", "[practice][cli]") {
    for (const char* args :
         {"--race 3", "--player2 Bob", "--breaks winner", "--vs-computer", "--resume"}) {
        INFO(args);
        const std::string out =
            tmux_session::run("'" + tmux_session::termpool_binary() + "' practice " + args +
                              " </dev/null 2>&1; echo \"status $?\"");
        CHECK(out.find("practice is one player at the table") != std::string::npos);
        CHECK(out.find("status 2") != std::string::npos);
    }
}
