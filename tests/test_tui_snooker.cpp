// The snooker table in the terminal: the baulk line, the D and the six colour spots at the
// cells their positions give, in every mode and at every size; the 22 balls told apart in
// every tier (reds "1", the colours by their values "2" to "7"); the balls drawn over the
// marks; pool balls on the snooker table keeping their numbers; the 2:1 layout; and the real
// binary's practice on the snooker table in tmux.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <termpool/rack.hpp>
#include <termpool/snooker_layout.hpp>
#include <termpool/table_physics.hpp>
#include <vector>

#include "ball_cells.hpp"
#include "tmux_session.hpp"
#include "tui/ball_style.hpp"
#include "tui/braille.hpp"
#include "tui/view.hpp"

using namespace termpool;
using namespace termpool::tui;

namespace {

const PhysicsParams params = physics_for_table(TableSize::snooker);
const Table snooker = make_table(TableSize::snooker, params.ball_radius);

struct Mode {
    const char* name;
    Capabilities caps;
};
const Mode modes[] = {{"colour", {256, true}},
                      {"8 colours", {8, true}},
                      {"mono", {0, true}},
                      {"ascii-colour", {256, false}},
                      {"ascii-mono", {0, false}}};

const std::pair<int, int> sizes[] = {{80, 24}, {100, 32}, {200, 60}, {120, 24},
                                     {60, 40}, {41, 15},  {300, 90}};

// The snooker rack (seed 3), the cue ball in the D.
View rack_view() {
    View v;
    v.table = &snooker;
    v.balls = make_rack(snooker, params, RackType::snooker, 3);
    v.ball_radius = params.ball_radius;
    v.practice = true;
    return v;
}

// A snooker set with every ball pocketed: the bare cloth, marked as a snooker table.
View bare_view() {
    View v = rack_view();
    for (Ball& b : v.balls)
        b.state = MotionState::pocketed;
    return v;
}

Ball ball(int id, Vec2 p) {
    Ball b;
    b.id = id;
    b.position = p;
    return b;
}

struct Cell2 {
    int x, y;
    auto operator<=>(const Cell2&) const = default;
};

Cell2 cell_of(const Layout& l, Vec2 p) {
    double col, row;
    to_cell(l, snooker.width, p, col, row);
    return {static_cast<int>(std::floor(col)), static_cast<int>(std::floor(row))};
}

bool on_felt(const Layout& l, Cell2 c) {
    const int fx = static_cast<int>(std::lround(l.table_left));
    const int fy = static_cast<int>(std::lround(l.table_top));
    return c.x >= fx && c.y >= fy && c.x < fx + l.felt_cols && c.y < fy + l.felt_rows;
}

// A cell of the marks: faint on the felt, not blank.
bool is_mark(const Cell& c, bool colour) {
    const Style faint = colour ? Style{Colour::dim, Colour::felt} : Style{};
    return c.style == faint && c.glyph != " ";
}

// The Braille dot bits of a glyph (U+2800..U+28FF), or -1 for anything else.
int braille_bits(const std::string& g) {
    if (g.size() != 3 || static_cast<unsigned char>(g[0]) != 0xE2 ||
        (static_cast<unsigned char>(g[1]) & 0xFC) != 0xA0)
        return -1;
    return ((static_cast<unsigned char>(g[1]) & 0x03) << 6) |
           (static_cast<unsigned char>(g[2]) & 0x3F);
}

constexpr int dot_bit[4][2] = {{0x01, 0x08}, {0x02, 0x10}, {0x04, 0x20}, {0x40, 0x80}};

// Points along the D's arc, from its top end round to its bottom end (behind the line).
std::vector<Vec2> arc_points(int n) {
    std::vector<Vec2> points;
    const Vec2 c = snooker_d_centre(snooker);
    const double r = snooker_d_radius_on(snooker);
    for (int k = 0; k <= n; ++k) {
        const double a = std::numbers::pi / 2 + std::numbers::pi * k / n;
        points.push_back(c + Vec2{std::cos(a), std::sin(a)} * r);
    }
    return points;
}

// True when the mark at the dot holding table point p is drawn, in that dot or one beside it
// (UTF-8; a spot's cell counts whole), or in its cell or one beside it (ASCII).
bool marked_near(const Grid& g, const Layout& l, Vec2 p, bool utf8, bool colour) {
    double col, row;
    to_cell(l, snooker.width, p, col, row);
    if (!utf8) {
        const Cell2 c = cell_of(l, p);
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                if (g.inside(c.x + dx, c.y + dy) && is_mark(g.at(c.x + dx, c.y + dy), colour))
                    return true;
        return false;
    }
    const int fx = static_cast<int>(std::lround(l.table_left));
    const int fy = static_cast<int>(std::lround(l.table_top));
    const int dx0 = static_cast<int>(std::floor((col - fx) * 2));
    const int dy0 = static_cast<int>(std::floor((row - fy) * 4));
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int x = dx0 + dx, y = dy0 + dy;
            if (x < 0 || y < 0)
                continue;
            const int cx = fx + x / 2, cy = fy + y / 4;
            if (!g.inside(cx, cy) || !is_mark(g.at(cx, cy), colour))
                continue;
            if (g.at(cx, cy).glyph == "\u00B7") // a spot on the line or the arc covers its dots
                return true;
            const int bits = braille_bits(g.at(cx, cy).glyph);
            if (bits >= 0 && (bits & dot_bit[y % 4][x % 2]))
                return true;
        }
    return false;
}

std::string spot_glyph(bool utf8) {
    return utf8 ? "\u00B7" : "+";
}

// A captured screen as rows of one-column glyphs (UTF-8 sequences).
std::vector<std::vector<std::string>> glyph_rows(const std::string& screen) {
    std::vector<std::vector<std::string>> rows(1);
    for (std::size_t i = 0; i < screen.size();) {
        if (screen[i] == '\n') {
            rows.emplace_back();
            ++i;
            continue;
        }
        std::size_t n = 1;
        while (i + n < screen.size() && (static_cast<unsigned char>(screen[i + n]) & 0xC0) == 0x80)
            ++n;
        rows.back().push_back(screen.substr(i, n));
        i += n;
    }
    return rows;
}

std::string glyph_at(const std::vector<std::vector<std::string>>& rows, int x, int y) {
    if (y < 0 || y >= static_cast<int>(rows.size()) || x < 0 ||
        x >= static_cast<int>(rows[static_cast<std::size_t>(y)].size()))
        return " ";
    return rows[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)];
}

} // namespace

TEST_CASE("the baulk line, the D and the six spots are drawn where they lie on the table",
          "[tui][snooker][snooker-tui]") {
    const View v = bare_view();
    const double baulk = snooker_baulk_x(snooker), W = snooker.width;
    const double r = snooker_d_radius_on(snooker);
    for (const auto& [w, h] : sizes)
        for (const Mode& mode : modes) {
            CAPTURE(w, h, mode.name);
            const Layout l = make_layout(snooker, w, h);
            REQUIRE(l.fits);
            const Grid g = render(v, l, mode.caps, w, h);
            const bool utf8 = mode.caps.utf8, colour = mode.caps.colours > 0;
            const int fy = static_cast<int>(std::lround(l.table_top));

            // The baulk line: one column, the whole width of the table, a dot wide in UTF-8.
            const int line_x = cell_of(l, {baulk, W / 2}).x;
            std::set<Cell2> spots;
            for (int c = snooker_yellow; c <= snooker_black; ++c)
                spots.insert(cell_of(l, snooker_spot(snooker, c)));
            for (int y = fy; y < fy + l.felt_rows; ++y) {
                CAPTURE(y);
                const Cell& cell = g.at(line_x, y);
                REQUIRE(is_mark(cell, colour));
                if (spots.count({line_x, y}))
                    continue;
                if (utf8)
                    CHECK(braille_bits(cell.glyph) >= 0);
                else
                    CHECK(cell.glyph == "|");
            }
            for (double y = 0.01; y < W; y += 0.05)
                CHECK(marked_near(g, l, {baulk, y}, utf8, colour));

            // The D: all along its arc, behind the line.
            for (const Vec2 p : arc_points(200)) {
                CAPTURE(p.x, p.y);
                CHECK(marked_near(g, l, p, utf8, colour));
            }
            // Its back reaches a radius behind the line.
            const Cell2 back = cell_of(l, {baulk - r, W / 2});
            CHECK(is_mark(g.at(back.x, back.y), colour));

            // The spots, in their own cells.
            for (int c = snooker_yellow; c <= snooker_black; ++c) {
                CAPTURE(c);
                const Cell2 s = cell_of(l, snooker_spot(snooker, c));
                REQUIRE(on_felt(l, s));
                CHECK(g.at(s.x, s.y).glyph == spot_glyph(utf8));
                CHECK(is_mark(g.at(s.x, s.y), colour));
            }

            // Nothing else: every mark on the felt is the line, the D or a spot, and the pool
            // table's head string and foot spot are not there.
            const std::vector<Vec2> arc = arc_points(400);
            const int fx = static_cast<int>(std::lround(l.table_left));
            for (int y = fy; y < fy + l.felt_rows; ++y)
                for (int x = fx; x < fx + l.felt_cols; ++x) {
                    if (!is_mark(g.at(x, y), colour))
                        continue;
                    CAPTURE(x, y);
                    const bool near_arc = std::any_of(arc.begin(), arc.end(), [&](Vec2 p) {
                        const Cell2 c = cell_of(l, p);
                        return std::abs(c.x - x) <= 1 && std::abs(c.y - y) <= 1;
                    });
                    CHECK((x == line_x || near_arc || spots.count({x, y}) > 0));
                    // The D opens towards the baulk cushion: nothing of it beyond the line.
                    CHECK(x <= line_x + (spots.count({x, y}) ? l.felt_cols : 0));
                }
        }
}

TEST_CASE("snooker balls show their values: reds 1, yellow 2 to black 7, in every tier",
          "[tui][snooker][snooker-tui]") {
    // Labels: told apart without colour and in ASCII, one cell each.
    for (const bool utf8 : {true, false})
        for (const bool wide : {true, false}) {
            std::set<std::string> labels;
            for (int id = snooker_first_red; id <= snooker_last_red; ++id)
                CHECK(ball_label(id, utf8, wide, BallSet::snooker) == "1");
            for (int id = snooker_yellow; id <= snooker_black; ++id) {
                const std::string label = ball_label(id, utf8, wide, BallSet::snooker);
                CHECK(label == std::to_string(snooker_value(id)));
                labels.insert(label);
            }
            CHECK(labels.size() == 6);
            CHECK(labels.count("1") == 0);
            CHECK(ball_label(0, utf8, wide, BallSet::snooker) == ball_label(0, utf8, wide));
        }
    // Styles: in colour on their own colours, the reds alike; without colour filled, the
    // colours bold as well.
    std::set<Colour> colours;
    for (int id = snooker_first_red; id <= snooker_black; ++id) {
        CAPTURE(id);
        const Style c = ball_style(id, true, BallSet::snooker);
        const Style m = ball_style(id, false, BallSet::snooker);
        CHECK(c.bg == ball_colour(id, BallSet::snooker));
        CHECK(c.bold);
        CHECK(m.reverse);
        CHECK(m.fg == Colour::normal);
        CHECK(m.bg == Colour::normal);
        CHECK(m.bold == is_snooker_colour(id));
        if (is_snooker_red(id))
            CHECK(c == ball_style(snooker_first_red, true, BallSet::snooker));
        else
            colours.insert(c.bg);
    }
    CHECK(ball_colour(snooker_first_red, BallSet::snooker) == Colour::red);
    CHECK(colours.size() == 6);
    CHECK(colours.count(Colour::red) == 0);
    CHECK(ball_style(snooker_black, true, BallSet::snooker).fg == Colour::white);

    // On the cloth: one of each colour and the cue ball, and a 1 on each cell that holds the
    // centre of a red and of no colour (reds a cell apart share it), at every size that has
    // room for the pack, in every tier.
    const View v = rack_view();
    REQUIRE(ball_set(v) == BallSet::snooker);
    for (const auto& [w, h] : {std::pair{80, 24}, {100, 32}, {200, 60}, {120, 24}})
        for (const Mode& mode : modes) {
            CAPTURE(w, h, mode.name);
            const Layout l = make_layout(snooker, w, h);
            const Grid g = render(v, l, mode.caps, w, h);
            std::map<std::string, int> seen;
            const int fx = static_cast<int>(std::lround(l.table_left));
            const int fy = static_cast<int>(std::lround(l.table_top));
            for (int y = fy; y < fy + l.felt_rows; ++y)
                for (int x = fx; x < fx + l.felt_cols; ++x) {
                    const Cell& c = g.at(x, y);
                    if (c.glyph.size() == 1 && c.glyph[0] >= '1' && c.glyph[0] <= '7') {
                        ++seen[c.glyph];
                        // As ball_style says, so the tiers differ only as the painter adapts.
                        const int id = c.glyph == "1" ? 1 : snooker_yellow + c.glyph[0] - '2';
                        Style want = ball_style(id, mode.caps.colours > 0, BallSet::snooker);
                        CHECK(c.style == want);
                    }
                    if (c.glyph == ball_label(0, mode.caps.utf8, false))
                        ++seen["cue"];
                }
            std::set<Cell2> red_cells, others;
            for (const Ball& b : v.balls)
                (is_snooker_red(b.id) ? red_cells : others).insert(cell_of(l, b.position));
            std::size_t reds = 0;
            for (const Cell2 c : red_cells)
                reds += others.count(c) == 0;
            CHECK(seen["1"] == static_cast<int>(reds));
            CHECK(termpool::test::misplaced_balls(
                      termpool::test::glyphs_of(g), v.balls, l, snooker.width,
                      {mode.caps.utf8, false, BallSet::snooker}) == std::vector<std::string>{});
            for (const char* colour : {"2", "3", "4", "5", "6", "7"}) {
                CAPTURE(colour);
                CHECK(seen[colour] == 1);
            }
            CHECK(seen["cue"] == 1);
        }
}

TEST_CASE("the balls are drawn over the baulk line, the D and the spots",
          "[tui][snooker][snooker-tui]") {
    // The colours on their spots, reds on the arc of the D and on the baulk line, the cue
    // ball on the line.
    View v = rack_view();
    const double baulk = snooker_baulk_x(snooker);
    const Vec2 c = snooker_d_centre(snooker);
    const double r = snooker_d_radius_on(snooker);
    v.balls.clear();
    for (int id = snooker_yellow; id <= snooker_black; ++id)
        v.balls.push_back(ball(id, snooker_spot(snooker, id)));
    int id = snooker_first_red;
    for (const double deg : {120.0, 150.0, 180.0, 210.0, 240.0}) {
        const double a = deg * std::numbers::pi / 180;
        v.balls.push_back(ball(id++, c + Vec2{std::cos(a), std::sin(a)} * r));
    }
    for (const double y : {0.15, 0.35, 1.45, 1.65})
        v.balls.push_back(ball(id++, {baulk, y}));
    v.balls.push_back(ball(0, {baulk, 1.25}));
    REQUIRE(ball_set(v) == BallSet::snooker);
    for (const auto& [w, h] : sizes)
        for (const Mode& mode : modes) {
            CAPTURE(w, h, mode.name);
            const Layout l = make_layout(snooker, w, h);
            const Grid g = render(v, l, mode.caps, w, h);
            std::set<Cell2> cells;
            for (const Ball& b : v.balls)
                cells.insert(cell_of(l, b.position));
            if (cells.size() != v.balls.size())
                continue; // two balls in one cell: one moves aside, which another test covers
            for (const Ball& b : v.balls) {
                CAPTURE(b.id);
                const Cell2 at = cell_of(l, b.position);
                const Cell& cell = g.at(at.x, at.y);
                CHECK(cell.glyph == ball_label(b.id, mode.caps.utf8, false, BallSet::snooker));
                if (b.id > 0)
                    CHECK(cell.style == (mode.caps.colours > 0
                                             ? ball_style(b.id, true, BallSet::snooker)
                                             : ball_style(b.id, false, BallSet::snooker)));
                CHECK_FALSE(is_mark(cell, mode.caps.colours > 0));
            }
        }
}

TEST_CASE("pool balls on the snooker table keep their numbers, and their head string shows",
          "[tui][snooker][snooker-tui]") {
    View v;
    v.table = &snooker;
    v.balls = make_rack(snooker, params, RackType::eight_ball);
    v.ball_radius = params.ball_radius;
    REQUIRE(ball_set(v) == BallSet::pool);
    for (const Mode& mode : modes) {
        CAPTURE(mode.name);
        const Layout l = make_layout(snooker, 100, 32);
        const Grid g = render(v, l, mode.caps, 100, 32);
        const bool colour = mode.caps.colours > 0;
        std::string felt;
        const int fx = static_cast<int>(std::lround(l.table_left));
        const int fy = static_cast<int>(std::lround(l.table_top));
        for (int y = fy; y < fy + l.felt_rows; ++y)
            for (int x = fx; x < fx + l.felt_cols; ++x)
                felt += g.at(x, y).glyph;
        // 1..9 and A..F at this size, as on a pool table, each on its own cell (or a mark
        // where its number would touch another).
        CHECK(termpool::test::misplaced_balls(
                  termpool::test::glyphs_of(g), v.balls, l, snooker.width,
                  {mode.caps.utf8, false, BallSet::pool}) == std::vector<std::string>{});
        CHECK(felt.find("8") != std::string::npos); // drawn first after the cue ball
        // The kitchen's line beside the baulk line, and the snooker marks still there.
        const int head = cell_of(l, {snooker.head_string_x(), 0.1}).x;
        const int line = cell_of(l, {snooker_baulk_x(snooker), 0.1}).x;
        CHECK(head > line);
        for (int y = fy; y < fy + l.felt_rows; ++y) {
            CHECK(is_mark(g.at(line, y), colour));
            if (g.at(head, y).glyph != ball_label(0, mode.caps.utf8, false))
                CHECK(is_mark(g.at(head, y), colour));
        }
    }
}

TEST_CASE("the legend counts the reds and lists the colours by value",
          "[tui][snooker][snooker-tui]") {
    View v = rack_view();
    for (Ball& b : v.balls)
        if (b.id == 2 || b.id == snooker_green)
            b.state = MotionState::pocketed;
    for (const Mode& mode : modes) {
        CAPTURE(mode.name);
        const Grid g = render(v, make_layout(snooker, 80, 24), mode.caps, 80, 24);
        std::string last;
        for (int x = 0; x < g.width; ++x)
            last += g.at(x, 23).glyph;
        CHECK(last.rfind("on table 1x14 2 4 5 6 7", 0) == 0);
    }
}

TEST_CASE("the snooker table keeps its 2:1 shape and fits the terminal at every size",
          "[tui][snooker][snooker-tui]") {
    for (const auto& [w, h] : sizes) {
        CAPTURE(w, h);
        const Layout l = make_layout(snooker, w, h);
        REQUIRE(l.fits);
        // Rows per metre r about half the columns per metre c: W r rows, L c columns, the
        // columns within 2 of the true shape's 2 L r, so a metre looks as long both ways.
        CHECK(l.felt_rows == Approx(snooker.width * l.rows_per_metre));
        CHECK(l.felt_cols == Approx(snooker.length * l.cells_per_metre));
        CHECK(std::abs(l.felt_cols - 2 * snooker.length * l.rows_per_metre) <= 2);
        const int x0 = static_cast<int>(std::lround(l.table_left)) - rail_cols;
        const int y0 = static_cast<int>(std::lround(l.table_top)) - rail_rows;
        CHECK(x0 >= 0);
        CHECK(y0 >= 0);
        CHECK(x0 + l.felt_cols + 2 * rail_cols <= (l.panel_below ? w : l.panel_x));
        CHECK(y0 + l.felt_rows + 2 * rail_rows <= l.status_y);
        // The black's spot, the farthest mark, is on the cloth.
        CHECK(on_felt(l, cell_of(l, snooker_spot(snooker, snooker_black))));
    }
}

TEST_CASE("practice on the snooker table in tmux shows the baulk line, the D and the spots",
          "[tui][e2e][snooker-tui]") {
    using namespace tmux_session;
    const ScratchDir scratch("termpool-snooker-e2e");
    for (const bool ascii : {false, true})
        for (const auto& [w, h] : {std::pair{100, 32}, {80, 24}}) {
            CAPTURE(ascii, w, h);
            Tmux t;
            t.start("env XDG_STATE_HOME=" + scratch.path + " TERM=xterm-256color LANG=C.UTF-8 " +
                        termpool_binary() + " practice --table snooker" + (ascii ? " --ascii" : ""),
                    w, h);
            REQUIRE(t.wait_for_text("Name of player 1"));
            t.keys("Enter");
            REQUIRE(t.wait_for_text("8-ball practice"));
            REQUIRE(t.wait_for([](const std::string& s) {
                return s.find("Name of player") == std::string::npos;
            }));
            // The aim along the centre line would cover the spots and the cue the D's back:
            // turned 30 degrees they are clear.
            t.repeat("Left", 30);
            const Layout l = make_layout(snooker, w, h);
            const Cell2 black = cell_of(l, snooker_spot(snooker, snooker_black));
            // Until all 30 turns are drawn: the black's spot clear and the screen still for
            // four polls in a row.
            std::string last;
            int still = 0;
            CHECK(t.wait_for([&](const std::string& s) {
                still = s == last ? still + 1 : 0;
                last = s;
                return still >= 4 &&
                       glyph_at(glyph_rows(s), black.x, black.y) == spot_glyph(!ascii);
            }));
            const auto rows = glyph_rows(t.screen());
            const int fy = static_cast<int>(std::lround(l.table_top));
            const int line_x = cell_of(l, {snooker_baulk_x(snooker), 0.1}).x;
            int line = 0;
            for (int y = fy; y < fy + l.felt_rows; ++y) {
                const std::string g = glyph_at(rows, line_x, y);
                line += (ascii ? g == "|" : braille_bits(g) > 0) || g == spot_glyph(!ascii);
            }
            CHECK(line >= l.felt_rows - 2); // the cue may cross it
            // The back of the D, a radius behind the line.
            const Vec2 c = snooker_d_centre(snooker);
            const Cell2 back = cell_of(l, {c.x - snooker_d_radius_on(snooker), c.y});
            const std::string b = glyph_at(rows, back.x, back.y);
            CHECK((ascii ? b == "(" : braille_bits(b) > 0));
            // The blue's and the black's spots (the rack covers the pink's).
            for (const int colour : {snooker_blue, snooker_black}) {
                const Cell2 s = cell_of(l, snooker_spot(snooker, colour));
                CHECK(glyph_at(rows, s.x, s.y) == spot_glyph(!ascii));
            }
        }
}
