// The close-up of the contact (z): the inset shows the cue ball at contact, the object ball and
// the contact point, names the cut angle and the aim to a hundredth of a degree, keeps clear
// of the cue ball and the contact on the table, and a 0.01-degree turn of the aim changes it.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <termpool/params.hpp>
#include <vector>

#include "tui/aid_path.hpp"
#include "tui/aim.hpp"
#include "tui/aim_state.hpp"
#include "tui/ball_style.hpp"
#include "tui/view.hpp"

using namespace termpool;
using namespace termpool::tui;

namespace {

const Table table = make_table(TableSize::nine_foot);
constexpr double R = 0.028575;

Ball ball(int id, Vec2 at) {
    Ball b;
    b.id = id;
    b.position = at;
    return b;
}

// The cue ball at `cue` aiming at `aim_deg` with the 5 at `object`, the close-up on or off, as
// the game fills the view from its aim.
View aiming(Vec2 cue, Vec2 object, double aim_deg, bool close_up = true) {
    View v;
    v.table = &table;
    v.balls = {ball(0, cue), ball(5, object)};
    v.aiming = true;
    v.show_aid = false;
    v.aim_deg = aim_deg;
    AimState aim;
    aim.aim_deg = aim_deg;
    aim.close_up = close_up;
    aim.full_preview = preview_shot(table, v.balls, R, cue, aim_deg);
    aim.preview = aim.full_preview;
    v.close_up = aim.close_up_view(v.balls);
    return v;
}

// The inset's cells, border included, as rows of glyphs; empty when there is none.
struct Inset {
    int x = -1, y = -1, w = 0, h = 0;
    std::vector<std::string> rows; // each row's glyphs joined
};

Inset find_inset(const Grid& g, bool utf8) {
    const std::string corner = utf8 ? "\u250C" : "+", end = utf8 ? "\u2510" : "+";
    const std::string bottom = utf8 ? "\u2514" : "+";
    Inset in;
    for (int y = 0; y < g.height && in.x < 0; ++y)
        for (int x = 0; x + 1 < g.width; ++x)
            if (g.at(x, y).glyph == corner && g.at(x + 1, y).glyph == (utf8 ? "\u2500" : "-")) {
                std::string top;
                for (int k = x; k < g.width; ++k)
                    top += g.at(k, y).glyph;
                if (top.find("close-up") == std::string::npos &&
                    top.find("cut ") == std::string::npos)
                    continue;
                in.x = x, in.y = y;
                int right = x + 1;
                while (right < g.width && g.at(right, y).glyph != end)
                    ++right;
                in.w = right - x + 1;
                int low = y + 1;
                while (low < g.height && g.at(x, low).glyph != bottom)
                    ++low;
                in.h = low - y + 1;
                break;
            }
    for (int y = in.y; in.x >= 0 && y < in.y + in.h; ++y) {
        std::string row;
        for (int x = in.x; x < in.x + in.w; ++x)
            row += g.at(x, y).glyph;
        in.rows.push_back(row);
    }
    return in;
}

bool has(const Inset& in, const std::string& text) {
    for (const std::string& row : in.rows)
        if (row.find(text) != std::string::npos)
            return true;
    return false;
}

std::string hundredths(double deg) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2f", deg);
    return buffer;
}

const Capabilities tiers[] = {{256, true}, {0, true}, {256, false}, {0, false}};

} // namespace

TEST_CASE("the close-up shows the cue ball, the object ball, the contact point and the cut",
          "[tui][closeup]") {
    // A thin cut: the cue ball's line passes 5 cm from the 5's centre, a metre away.
    const Vec2 cue{0.8, 0.5}, object{1.8, 0.55};
    const double aim = 0;
    for (const auto& [w, h] : {std::pair{100, 32}, {80, 24}, {200, 60}, {120, 40}})
        for (const Capabilities& caps : tiers) {
            CAPTURE(w, h, caps.colours, caps.utf8);
            const View v = aiming(cue, object, aim);
            REQUIRE(v.close_up.ball == 5);
            const Layout l = make_layout(table, w, h);
            const Grid g = render(v, l, caps, w, h);
            const Inset in = find_inset(g, caps.utf8);
            REQUIRE(in.x >= 0);
            CAPTURE(in.rows);
            // Inside the felt, clear of the cue ball and the contact on the table.
            const int fx = static_cast<int>(std::lround(l.table_left));
            const int fy = static_cast<int>(std::lround(l.table_top));
            CHECK(in.x >= fx);
            CHECK(in.y >= fy);
            CHECK(in.x + in.w <= fx + l.felt_cols);
            CHECK(in.y + in.h <= fy + l.felt_rows);
            for (const Vec2 p : {cue, (v.close_up.cue + object) * 0.5}) {
                double col, row;
                to_cell(l, table.width, p, col, row);
                const bool covered =
                    col >= in.x && col < in.x + in.w && row >= in.y && row < in.y + in.h;
                CHECK_FALSE(covered);
            }
            // The cut: the angle between the cue ball's line and the line of centres.
            const Vec2 centres = object - v.close_up.cue;
            const double cut = std::acos(centres.x / length(centres)) * 180 / std::numbers::pi;
            CHECK(cut > 60);
            CHECK(has(in, "cut " + hundredths(cut)));
            CHECK(has(in, "aim " + hundredths(aim)));
            // Both balls by their labels, the contact point, and the circles' dots.
            CHECK(has(in, ball_label(0, caps.utf8, false)));
            CHECK(has(in, "5"));
            CHECK(has(in, "+"));
            int dots = 0;
            for (const std::string& row : in.rows)
                for (std::size_t i = 0; i + 2 < row.size(); ++i)
                    dots += caps.utf8 ? row.compare(i, 2, "\xE2\xA0") == 0 ||
                                            row.compare(i, 2, "\xE2\xA1") == 0 ||
                                            row.compare(i, 2, "\xE2\xA2") == 0 ||
                                            row.compare(i, 2, "\xE2\xA3") == 0
                                      : row[i] == '.';
            CHECK(dots > 20);
            CHECK(in.w >= 16 + 2);
        }
}

TEST_CASE("a 0.01-degree turn of the aim changes the close-up", "[tui][closeup]") {
    const Vec2 cue{0.8, 0.5}, object{1.8, 0.55};
    for (const auto& [w, h] : {std::pair{100, 32}, {80, 24}})
        for (const double step : {0.01, -0.01, 0.1}) {
            CAPTURE(w, h, step);
            const Layout l = make_layout(table, w, h);
            const Inset before = find_inset(render(aiming(cue, object, 0.0), l, {}, w, h), true);
            const Inset after =
                find_inset(render(aiming(cue, object, turn(0.0, step)), l, {}, w, h), true);
            REQUIRE(before.x >= 0);
            REQUIRE(after.x >= 0);
            CHECK(before.rows != after.rows);
            CHECK(has(after, "aim " + hundredths(turn(0.0, step))));
        }
    // A thin cut swings fast: a hundredth of a degree of aim a metre away is a tenth of a
    // degree of cut and more.
    const View a = aiming(cue, object, 0.0), b = aiming(cue, object, 0.01);
    const Vec2 ca = object - a.close_up.cue, cb = object - b.close_up.cue;
    const double da = std::atan2(ca.y, ca.x), db = std::atan2(cb.y, cb.x);
    CHECK(std::fabs(da - db) * 180 / std::numbers::pi > 0.1);
}

TEST_CASE("the close-up is drawn only when shown, and says when no ball is in line",
          "[tui][closeup]") {
    const Layout l = make_layout(table, 100, 32);
    // Off: no inset.
    CHECK(find_inset(render(aiming({0.8, 0.5}, {1.8, 0.55}, 0, false), l, {}, 100, 32), true).x <
          0);
    // Not while placing the cue ball or watching.
    View placing = aiming({0.8, 0.5}, {1.8, 0.55}, 0);
    placing.placing = true;
    CHECK(find_inset(render(placing, l, {}, 100, 32), true).x < 0);
    // Aimed away from the ball, into a cushion.
    const View away = aiming({0.8, 0.5}, {1.8, 0.55}, 180);
    CHECK(away.close_up.ball < 0);
    const Grid g = render(away, l, {}, 100, 32);
    std::string all;
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x)
            all += g.at(x, y).glyph;
    CHECK(all.find("close-up") != std::string::npos);
    CHECK(all.find("no ball in line") != std::string::npos);
}

TEST_CASE("the close-up writes inside the grid at any size", "[tui][closeup]") {
    for (int w = 1; w <= 130; w += 7)
        for (int h = 1; h <= 50; h += 3)
            for (const Vec2 cue : {Vec2{0.1, 0.1}, Vec2{2.4, 1.2}, Vec2{1.27, 0.635}}) {
                View v = aiming(cue, {1.9, 0.3},
                                std::atan2(0.3 - cue.y, 1.9 - cue.x) * 180 / std::numbers::pi);
                const Grid g = render(v, make_layout(table, w, h), {}, w, h);
                CHECK(g.cells.size() == static_cast<std::size_t>(std::max(w, 0) * std::max(h, 0)));
            }
}

TEST_CASE("the close-up takes the corner where it hides no ball", "[tui][closeup]") {
    // The contact up and to the right, a ball in the corner farthest from it (where the inset
    // would go) and near two others: the inset goes to the fourth, and every ball stays in
    // sight.
    const Vec2 cue{1.4, 0.8}, object{1.9, 0.82};
    for (const auto& [w, h] : {std::pair{100, 32}, {80, 24}, {200, 60}}) {
        CAPTURE(w, h);
        View v = aiming(cue, object, 0);
        v.balls.push_back(ball(1, {0.25, 0.22}));
        v.balls.push_back(ball(2, {2.3, 1.05}));
        v.balls.push_back(ball(3, {2.3, 0.22}));
        const Layout l = make_layout(table, w, h);
        const Grid g = render(v, l, Capabilities{256, true}, w, h);
        const Inset in = find_inset(g, true);
        REQUIRE(in.x >= 0);
        for (const Ball& b : v.balls) {
            CAPTURE(b.id);
            double col, row;
            to_cell(l, table.width, b.position, col, row);
            CHECK_FALSE((col >= in.x && col < in.x + in.w && row >= in.y && row < in.y + in.h));
        }
    }
}

TEST_CASE("the close-up shows the contact at every assist, the way out only where it is shown",
          "[tui][closeup]") {
    // Pro draws nothing after the first contact, yet the contact itself is the cue's: the
    // inset still shows the ball met and where, without the object ball's line out.
    const Vec2 cue{0.8, 0.5}, object{1.8, 0.55};
    const std::vector<Ball> balls = {ball(0, cue), ball(5, object)};
    for (const Assist level : {Assist::guided, Assist::standard, Assist::pro}) {
        CAPTURE(static_cast<int>(level));
        AimState aim;
        aim.close_up = true;
        aim.full_preview = preview_shot(table, balls, R, cue, 0);
        aim.preview = shown_preview(aim.full_preview, level, R);
        const CloseUp c = aim.close_up_view(balls);
        CHECK(c.ball == 5);
        CHECK(length(c.cue - aim.full_preview.ghost) == 0);
        CHECK((length(c.departure) > 0) == (level != Assist::pro));
    }
}
