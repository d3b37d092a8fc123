// Input math of the terminal game: aim angles, power, spin, player names, text width and the
// aiming aid's geometry.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "physics_helpers.hpp"
#include "player/player_name.hpp"
#include "tui/aim.hpp"
#include <termpool/text_width.hpp>

using namespace termpool;
using namespace termpool::tui;
using termpool::test::ball_at;

namespace {

const Table table = make_table(TableSize::nine_foot);
constexpr double R = 0.028575;

std::string repeat(const std::string& s, int n) {
    std::string out;
    for (int i = 0; i < n; ++i)
        out += s;
    return out;
}

} // namespace

TEST_CASE("aim from the pointer over the full circle", "[tui]") {
    const Vec2 cue{1.0, 0.6};
    CHECK(aim_from_pointer(cue, cue + Vec2{1, 0}) == 0);
    CHECK(aim_from_pointer(cue, cue + Vec2{0, 0.3}) == Approx(90));
    CHECK(aim_from_pointer(cue, cue + Vec2{-0.2, 0}) == Approx(180));
    CHECK(aim_from_pointer(cue, cue + Vec2{0, -0.3}) == Approx(270));
    CHECK(aim_from_pointer(cue, cue) == 0);
    for (double deg = 0; deg < 360; deg += 0.7) {
        const double a = deg * M_PI / 180;
        const double got = aim_from_pointer(cue, cue + Vec2{std::cos(a), std::sin(a)} * 0.4);
        CHECK(got >= 0);
        CHECK(got < 360);
        CHECK(std::fabs(std::remainder(got - deg, 360.0)) < 1e-9);
    }
}

TEST_CASE("turning wraps to [0, 360) and 0.1-degree steps stay exact", "[tui]") {
    CHECK(turn(359.5, 1) == Approx(0.5));
    CHECK(turn(0, -0.1) == Approx(359.9));
    CHECK(turn(0, -1e-12) < 360);
    CHECK(turn(90, 360) == Approx(90));
    CHECK(turn(10, -730) == Approx(0));
    double a = 0;
    for (int i = 0; i < 10; ++i)
        a = turn(a, 0.1);
    CHECK(a == 1.0);
    for (int i = 0; i < 3600; ++i)
        a = turn(a, 0.1);
    CHECK(a == 1.0);
    for (int i = 0; i < 20; ++i)
        a = turn(a, -0.1);
    CHECK(a == Approx(359.0));
}

TEST_CASE("power from distance and from time", "[tui]") {
    CHECK(power_from_distance(0) == 0);
    CHECK(power_from_distance(-1) == 0);
    CHECK(power_from_distance(0.25) == Approx(0.25));
    CHECK(power_from_distance(0.5) == Approx(0.5));
    CHECK(power_from_distance(1.0) == 1);
    CHECK(power_from_distance(3.0) == 1);
    CHECK(power_from_distance(NAN) == 0);

    CHECK(power_from_time(0) == 0);
    CHECK(power_from_time(0.375) == Approx(0.5));
    CHECK(power_from_time(0.75) == Approx(1));
    CHECK(power_from_time(1.125) == Approx(0.5));
    CHECK(power_from_time(1.5) == Approx(0).margin(1e-12));
    CHECK(power_from_time(2.25) == Approx(1));
    CHECK(power_from_time(1, 2) == Approx(1));
    CHECK(power_from_time(0.5, 2) == Approx(0.5));
    for (double t = 0; t < 10; t += 0.01) {
        const double p = power_from_time(t);
        CHECK(p >= 0);
        CHECK(p <= 1);
    }

    CHECK(speed_from_power(0, false) == Approx(0.3));
    CHECK(speed_from_power(1, false) == Approx(7));
    CHECK(speed_from_power(1, true) == Approx(12));
    CHECK(speed_from_power(0, true) == Approx(0.3));
    CHECK(speed_from_power(0.5, true) == Approx(0.3 + 0.5 * 11.7));
    CHECK(speed_from_power(2, false) == Approx(7));
    CHECK(speed_from_power(-1, false) == Approx(0.3));
}

TEST_CASE("spin steps are clamped and tidy", "[tui]") {
    CHECK(clamp_spin(0.7) == 0.5);
    CHECK(clamp_spin(-0.7) == -0.5);
    CHECK(clamp_spin(NAN) == 0);
    double s = 0;
    for (int i = 0; i < 3; ++i)
        s = clamp_spin(s + 0.1);
    CHECK(s == 0.3);
    for (int i = 0; i < 10; ++i)
        s = clamp_spin(s + 0.1);
    CHECK(s == 0.5);
}

TEST_CASE("display width of UTF-8 text", "[tui]") {
    CHECK(display_width("Alice") == 5);
    CHECK(display_width("山田") == 4);
    CHECK(display_width("e\u0301") == 1);
    CHECK(display_width("\U0001F600") == 2);
    CHECK(display_width("한국") == 4);
    CHECK(display_width("ｆｕｌｌ") == 8);
    CHECK(display_width("\xff") == 1);
    CHECK(truncate_to_width("山田", 3) == "山");
    CHECK(truncate_to_width("ab山", 3) == "ab");
    CHECK(truncate_to_width("ae\u0301b", 2) == "ae\u0301");
    CHECK(truncate_to_width("abc", 0).empty());
    CHECK(valid_utf8("Zoë 山田 \U0001F600"));
    CHECK_FALSE(valid_utf8("\xc0\xaf"));         // overlong
    CHECK_FALSE(valid_utf8("\xed\xa0\x80"));     // surrogate
    CHECK_FALSE(valid_utf8("\xf4\x90\x80\x80")); // above U+10FFFF
    CHECK_FALSE(valid_utf8("\xe4\xb8"));         // truncated
    CHECK_FALSE(valid_utf8("\x80"));             // stray continuation
}

TEST_CASE("text wraps at words and keeps long words", "[tui]") {
    const auto lines = wrap_to_width("the quick brown fox jumps", 10);
    REQUIRE(lines.size() == 3);
    CHECK(lines[0] == "the quick");
    CHECK(lines[1] == "brown fox");
    CHECK(lines[2] == "jumps");
    const auto cut = wrap_to_width("abcdefghijkl", 5);
    REQUIRE(cut.size() == 3);
    CHECK(cut[0] == "abcde");
    CHECK(cut[2] == "kl");
    CHECK(wrap_to_width("a\n\nb", 5).size() == 3);
    for (const auto& line : wrap_to_width("山田太郎さんのチーム", 5))
        CHECK(display_width(line) <= 5);
}

TEST_CASE("player names: trimmed, at most 20 columns, no control characters", "[tui]") {
    std::string error;
    CHECK(clean_player_name("  Alice  ", error) == std::optional<std::string>("Alice"));
    CHECK(error.empty());
    CHECK(clean_player_name("Zoë", error) == std::optional<std::string>("Zoë"));

    // Empty keeps the default.
    CHECK_FALSE(clean_player_name("", error));
    CHECK(error.empty());
    CHECK_FALSE(clean_player_name("     ", error));
    CHECK(error.empty());

    // 20 columns: ASCII, wide CJK counting two, a mix that cannot split a wide character.
    CHECK(clean_player_name(repeat("a", 25), error) == std::optional(repeat("a", 20)));
    CHECK(clean_player_name(repeat("山", 11), error) == std::optional(repeat("山", 10)));
    const auto mixed = clean_player_name("a" + repeat("山", 10), error);
    REQUIRE(mixed);
    CHECK(*mixed == "a" + repeat("山", 9));
    CHECK(display_width(*mixed) == 19);
    CHECK(valid_utf8(*mixed));
    // A cut right after a space leaves no trailing space.
    CHECK(clean_player_name(repeat("b", 19) + " cd", error) == std::optional(repeat("b", 19)));
    // A combining mark stays with its letter.
    CHECK(clean_player_name(repeat("x", 19) + "e\u0301z", error) ==
          std::optional(repeat("x", 19) + "e\u0301"));

    // Control characters and invalid UTF-8 are refused with a message.
    for (const std::string& bad :
         {std::string("a\tb"), std::string("a\nb"), std::string("\x1b[31m"), std::string("del\x7f"),
          std::string("c1\xc2\x85"), std::string("nul", 4), std::string("\xff"),
          std::string("\xc3"), std::string("\xc0\xaf"), std::string("\xed\xa0\x80")}) {
        CAPTURE(bad);
        error.clear();
        CHECK_FALSE(clean_player_name(bad, error));
        CHECK_FALSE(error.empty());
    }
}

TEST_CASE("preview: straight at a ball the ghost ball touches it", "[tui]") {
    const std::vector<Ball> balls{ball_at(0, 0.5, 0.6), ball_at(1, 1.5, 0.6)};
    const AimPreview p = preview_shot(table, balls, R, {0.5, 0.6}, 0);
    REQUIRE(p.has_ghost);
    CHECK(p.object_ball == 1);
    CHECK(p.cushion == -1);
    CHECK(length(p.ghost - balls[1].position) == Approx(2 * R).epsilon(1e-12));
    CHECK(p.ghost.y == Approx(0.6));
    REQUIRE(p.cue_path.size() == 2);
    CHECK(p.cue_path.front() == Vec2{0.5, 0.6});
    CHECK(p.cue_path.back() == p.ghost);
    // Full hit: the object ball goes straight on (to the far cushion), the cue ball stops.
    REQUIRE(p.object_path.size() == 2);
    const Vec2 dir = normalized(p.object_path[1] - p.object_path[0]);
    CHECK(dir.x == Approx(1));
    CHECK(dir.y == Approx(0).margin(1e-12));
    CHECK(p.deflect_path.empty());
}

TEST_CASE("preview: a cut sends the balls along the line of centres and the tangent", "[tui]") {
    const std::vector<Ball> balls{ball_at(0, 0.5, 0.6), ball_at(3, 1.5, 0.63)};
    const AimPreview p = preview_shot(table, balls, R, {0.5, 0.6}, 0);
    REQUIRE(p.has_ghost);
    CHECK(length(p.ghost - balls[1].position) == Approx(2 * R).epsilon(1e-12));
    const Vec2 n = normalized(balls[1].position - p.ghost);
    REQUIRE(p.object_path.size() == 2);
    REQUIRE(p.deflect_path.size() == 2);
    const Vec2 o = normalized(p.object_path[1] - p.object_path[0]);
    const Vec2 t = normalized(p.deflect_path[1] - p.deflect_path[0]);
    CHECK(o.x == Approx(n.x));
    CHECK(o.y == Approx(n.y));
    CHECK(dot(t, n) == Approx(0).margin(1e-12)); // 90 degrees
    CHECK(t.y < 0);                              // away from the ball, which was above the line
    CHECK(t.x > 0);
    CHECK(p.deflect_path[0] == p.ghost);
    CHECK(length(p.object_path[1] - p.object_path[0]) <= 0.6 + 1e-12);
}

TEST_CASE("preview: at a cushion the path ends R from it", "[tui]") {
    const std::vector<Ball> balls{ball_at(0, 1.0, 0.6)};
    struct Case {
        double deg;
        double x, y; // expected end; NaN = any
    };
    for (const Case c : {Case{90, 1.0, table.width - R}, Case{270, 1.0, R},
                         Case{0, table.length - R, 0.6}, Case{180, R, 0.6}}) {
        CAPTURE(c.deg);
        const AimPreview p = preview_shot(table, balls, R, {1.0, 0.6}, c.deg);
        CHECK_FALSE(p.has_ghost);
        CHECK(p.object_ball == -1);
        CHECK(p.cushion >= 0);
        REQUIRE(p.cue_path.size() == 2);
        CHECK(p.cue_path[1].x == Approx(c.x).margin(1e-12));
        CHECK(p.cue_path[1].y == Approx(c.y).margin(1e-12));
    }
    for (double deg = 3; deg < 360; deg += 11) {
        const AimPreview p = preview_shot(table, balls, R, {1.0, 0.6}, deg);
        const Vec2 e = p.cue_path.back();
        const double to_rail = std::min({e.x, table.length - e.x, e.y, table.width - e.y});
        CAPTURE(deg, e.x, e.y);
        // On a rail line R from the cushion, or (towards a pocket) between the jaws.
        if (p.cushion >= 0 && p.cushion < 6)
            CHECK(to_rail == Approx(R).margin(1e-9));
        CHECK(e.x > -0.2);
        CHECK(e.x < table.length + 0.2);
    }
    // Straight into a corner pocket the path runs into the mouth.
    const AimPreview corner = preview_shot(table, {ball_at(0, 0.4, 0.4)}, R, {0.4, 0.4}, 225);
    CHECK(corner.cue_path.back().x < R);
    CHECK(corner.cue_path.back().y < R);
}

TEST_CASE("targets are ranked easiest first", "[tui]") {
    // Ball 1 sits straight between the cue ball and corner pocket 3; ball 2 needs a thin cut
    // to any pocket; ball 3 is not a legal target (and off ball 1's line to the pocket).
    const Vec2 cue{1.4, 0.4};
    const std::vector<Ball> balls{ball_at(0, cue.x, cue.y), ball_at(1, 2.0, 0.2),
                                  ball_at(2, 1.9, 1.0), ball_at(3, 2.3, 0.9)};
    const std::vector<int> order = targets_easiest_first(table, balls, R, cue, {1, 2});
    REQUIRE(order == std::vector<int>{1, 2});
    const auto ranked = rank_targets(table, balls, R, cue, {1, 2});
    REQUIRE(ranked.size() == 2);
    CHECK(ranked[0].pocket == 3);
    CHECK(ranked[0].difficulty < ranked[1].difficulty);
    // Its aim points at the ghost ball, which sends ball 1 into pocket 3.
    const AimPreview p = preview_shot(table, balls, R, cue, ranked[0].aim_deg);
    REQUIRE(p.object_ball == 1);
    const Vec2 dir = normalized(balls[1].position - p.ghost);
    const Vec2 want = normalized(table.pockets[2].position - balls[1].position);
    CHECK(dot(dir, want) == Approx(1).margin(1e-9));
    CHECK(targets_easiest_first(table, balls, R, cue, {}).empty());
}

TEST_CASE("the proposed aim never meets another ball first", "[tui]") {
    // Ball 2 covers the straight line from the cue ball to ball 1 but leaves a thin edge of
    // it in view; ball 1 is legal, ball 2 is not.
    const Vec2 cue{0.6, 0.6};
    const std::vector<Ball> balls{ball_at(0, cue.x, cue.y), ball_at(1, 1.6, 0.6),
                                  ball_at(2, 1.1, 0.64)};
    const auto ranked = rank_targets(table, balls, R, cue, {1});
    REQUIRE(ranked.size() == 1);
    // Straight at ball 1 the cue ball would hit ball 2 first.
    CHECK(
        preview_shot(table, balls, R, cue, aim_from_pointer(cue, balls[1].position)).object_ball ==
        2);
    const AimPreview p = preview_shot(table, balls, R, cue, ranked[0].aim_deg);
    CHECK(p.object_ball == 1);

    // A blocker on the line from ball 1 to its best pocket makes that pocket harder.
    const std::vector<Ball> open{ball_at(0, 1.4, 0.4), ball_at(1, 2.0, 0.2)};
    const std::vector<Ball> blocked{ball_at(0, 1.4, 0.4), ball_at(1, 2.0, 0.2),
                                    ball_at(5, 2.2, 0.14)};
    const auto easy = rank_targets(table, open, R, {1.4, 0.4}, {1});
    const auto hard = rank_targets(table, blocked, R, {1.4, 0.4}, {1});
    REQUIRE(easy.size() == 1);
    REQUIRE(hard.size() == 1);
    CHECK(easy[0].pocket == 3);
    CHECK(hard[0].difficulty > easy[0].difficulty);

    // Fully hidden behind ball 2: no clear line, so it is ranked after a visible target.
    const std::vector<Ball> hidden{ball_at(0, 0.6, 0.6), ball_at(1, 1.2, 0.6), ball_at(2, 0.7, 0.6),
                                   ball_at(3, 0.6, 1.0)};
    const auto order = targets_easiest_first(table, hidden, R, {0.6, 0.6}, {1, 3});
    CHECK(order == std::vector<int>{3, 1});
    // It is offered as a one-rail kick: the cue ball meets a rail first.
    const auto kick = rank_targets(table, hidden, R, {0.6, 0.6}, {1});
    REQUIRE(kick.size() == 1);
    CHECK(kick[0].line == TargetLine::kick);
    CHECK(preview_shot(table, hidden, R, {0.6, 0.6}, kick[0].aim_deg).cushion >= 0);
}
