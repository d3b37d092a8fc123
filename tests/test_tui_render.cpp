// The renderer: golden frames of the 8-ball rack and a crowded table in every display mode,
// ball labels that read as the balls' numbers, the panel, the help's pages, overlays clear of
// the balls, the cue and aim line in every direction, sub-cell precision, and safety at any
// size.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <termpool/rack.hpp>
#include <termpool/table_physics.hpp>

#include "ball_cells.hpp"
#include "tui/ball_style.hpp"
#include "tui/grid_dump.hpp"
#include "tui/help_text.hpp"
#include "tui/pocket_cells.hpp"
#include "tui/view.hpp"
#include "tui_frames.hpp"
#include <termpool/text_width.hpp>

using namespace termpool;
using namespace termpool::tui;
using termpool::test::cell_at;
using termpool::test::crowded_view;
using termpool::test::glyphs_of;
using termpool::test::misplaced_balls;
using termpool::test::rack_view;

namespace {

const Table table = make_table(TableSize::nine_foot);
constexpr double R = 0.028575;

struct Mode {
    const char* name;
    Capabilities caps;
};
const Mode modes[] = {{"colour", {256, true}},
                      {"mono", {0, true}},
                      {"ascii-colour", {256, false}},
                      {"ascii-mono", {0, false}}};

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return {};
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The first line where two dumps differ, for the failure message.
std::string first_difference(const std::string& want, const std::string& got) {
    std::istringstream a(want), b(got);
    std::string la, lb;
    for (int n = 1;; ++n) {
        const bool ha = static_cast<bool>(std::getline(a, la));
        const bool hb = static_cast<bool>(std::getline(b, lb));
        if (!ha && !hb)
            return "no difference";
        if (la != lb || ha != hb)
            return "line " + std::to_string(n) + "\n  golden: " + la + "\n  render: " + lb;
    }
}

Grid draw(const View& v, int w, int h, Capabilities caps = {256, true}) {
    return render(v, make_layout(table, w, h), caps, w, h);
}

// A view with only the cue ball, aiming at `deg`.
View cue_only(double deg, Vec2 at = {1.27, 0.635}) {
    View v;
    v.table = &table;
    Ball cue;
    cue.position = at;
    v.balls = {cue};
    v.aiming = true;
    v.show_aid = false;
    v.aim_deg = deg;
    return v;
}

// The grid's glyphs, a line per row.
std::string screen_text(const Grid& g) {
    std::string all;
    for (int y = 0; y < g.height; ++y) {
        for (int x = 0; x < g.width; ++x)
            all += g.at(x, y).glyph;
        all += '\n';
    }
    return all;
}

// The glyphs of row y from column x0 up to x1.
std::string row_text(const Grid& g, int y, int x0 = 0, int x1 = INT_MAX) {
    std::string s;
    for (int x = std::max(0, x0); x < std::min(x1, g.width); ++x)
        s += g.at(x, y).glyph;
    return s;
}

// The cell where `text` starts on the screen (the first from the top left), or {-1, -1}.
std::pair<int, int> find_cell(const Grid& g, const std::string& text) {
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) {
            std::string s;
            for (int k = x; k < g.width && s.size() < text.size(); ++k)
                s += g.at(k, y).glyph;
            if (s == text)
                return {x, y};
        }
    return {-1, -1};
}

// Runs of white space as one space.
std::string words(const std::string& text) {
    std::string out;
    for (const char c : text)
        if (!std::isspace(static_cast<unsigned char>(c)))
            out += c;
        else if (!out.empty() && out.back() != ' ')
            out += ' ';
    return out;
}

// True for a cell of a ball's label: a digit, a letter A-F, the cue ball or the mark of a
// ball whose number gave way.
bool is_label_glyph(const std::string& glyph, bool utf8) {
    return glyph == ball_label(0, utf8, false) || glyph == ball_mark(utf8) ||
           (glyph.size() == 1 && (std::isdigit(static_cast<unsigned char>(glyph[0])) ||
                                  (glyph[0] >= 'A' && glyph[0] <= 'F')));
}

// What is wrong with where v's balls are drawn in g (see misplaced_balls).
std::vector<std::string> misplaced(const Grid& g, const View& v, const Layout& l, bool utf8) {
    return misplaced_balls(glyphs_of(g), v.balls, l, table.width,
                           {utf8, wide_labels(l.cells_per_metre, R), ball_set(v)});
}

bool is_cue_glyph(const std::string& g) {
    return g == "-" || g == "/" || g == "|" || g == "\\" || g == "\u2500" || g == "\u2571" ||
           g == "\u2502" || g == "\u2572";
}

} // namespace

TEST_CASE("golden frames of the 8-ball rack and a crowded table", "[tui][golden]") {
    const bool update = std::getenv("TERMPOOL_UPDATE_GOLDEN") != nullptr &&
                        std::string(std::getenv("TERMPOOL_UPDATE_GOLDEN")) == "1";
    const std::pair<const char*, View> views[] = {{"rack", rack_view(table)},
                                                  {"crowded", crowded_view(table)}};
    for (const auto& [name, view] : views)
        for (const auto& [w, h] : {std::pair{80, 24}, {100, 32}, {200, 60}})
            for (const Mode& mode : modes) {
                const std::string path = std::string("tests/golden/") + name + "_" +
                                         std::to_string(w) + "x" + std::to_string(h) + "_" +
                                         mode.name + ".txt";
                CAPTURE(path);
                const std::string got = dump_grid(draw(view, w, h, mode.caps));
                if (update) {
                    std::ofstream(path, std::ios::binary) << got;
                    WARN("rewrote " << path);
                    continue;
                }
                const std::string want = read_file(path);
                INFO("run with TERMPOOL_UPDATE_GOLDEN=1 to rewrite the goldens after a deliberate "
                     "change, then look at them");
                INFO(first_difference(want, got));
                const bool same = want == got; // not CHECK(want == got): that prints whole frames
                CHECK(same);
            }
}

TEST_CASE("the golden comparison sees a single changed cell", "[tui][golden]") {
    const Grid grid = draw(rack_view(table), 80, 24);
    const std::string base = dump_grid(grid);
    Grid glyph = grid;
    glyph.at(40, 12).glyph = glyph.at(40, 12).glyph == "x" ? "y" : "x";
    CHECK(dump_grid(glyph) != base);
    Grid bold = grid;
    bold.at(0, 23).style.bold = !bold.at(0, 23).style.bold;
    CHECK(dump_grid(bold) != base);
    Grid colour = grid;
    colour.at(79, 0).style.bg =
        colour.at(79, 0).style.bg == Colour::felt ? Colour::rail : Colour::felt;
    CHECK(dump_grid(colour) != base);
}

TEST_CASE("the rack frame shows every ball, the cue ball in the kitchen and the pockets", "[tui]") {
    const View view = rack_view(table);
    for (const Mode& mode : modes) {
        CAPTURE(mode.name);
        const Layout l = make_layout(table, 200, 60);
        const Grid g = render(view, l, mode.caps, 200, 60);
        REQUIRE(wide_labels(l.cells_per_metre, R));
        for (const Ball& b : view.balls) {
            double col, row;
            to_cell(l, table.width, b.position, col, row);
            // At this size each ball has its own cells: its number, centred on its centre.
            const std::string want =
                b.id == 0 ? (mode.caps.utf8 ? "\u25CF" : "o") : std::to_string(b.id);
            const int x = static_cast<int>(std::floor(col - (b.id >= 10 ? 0.5 : 0)));
            std::string got;
            for (int k = 0; k < (b.id >= 10 ? 2 : 1); ++k)
                got += g.at(x + k, static_cast<int>(row)).glyph;
            CHECK(got == want);
            if (b.id == 0)
                CHECK(b.position.x <= table.head_string_x());
        }
        for (int n = 1; n <= 6; ++n) {
            const PocketCells p = pocket_cells(table, l, n);
            REQUIRE(p.cells.size() >= 2);
            for (const auto& [x, y] : p.cells)
                CHECK(g.at(x, y).style.bg == (mode.caps.colours ? Colour::pocket : Colour::normal));
        }
    }
}

TEST_CASE("ball styles: solids on their colour, stripes on white, monochrome by attributes",
          "[tui]") {
    View v = rack_view(table);
    v.aiming = false;
    const Layout l = make_layout(table, 200, 60);
    const Grid colour = render(v, l, {256, true}, 200, 60);
    const Grid mono = render(v, l, {0, true}, 200, 60);
    for (const Ball& b : v.balls) {
        if (b.id == 0)
            continue;
        double col, row;
        to_cell(l, table.width, b.position, col, row);
        const int x = static_cast<int>(col), y = static_cast<int>(row);
        const Style c = colour.at(x, y).style, m = mono.at(x, y).style;
        CAPTURE(b.id);
        if (b.id == 8) {
            CHECK(c.fg == Colour::white);
            CHECK(c.bg == Colour::black);
            CHECK((m.reverse && m.bold));
        } else if (b.id < 8) {
            CHECK(c.fg == Colour::ink); // dark digits in the terminal's own black
            CHECK(c.bold);
            CHECK(c.bg != Colour::white);
            CHECK(m.reverse);
            CHECK_FALSE(m.bold);
        } else {
            CHECK(c.bg == Colour::white);
            CHECK(c.fg != Colour::white);
            CHECK_FALSE(m.reverse);
            CHECK(m.bold);
        }
        // Same colour for n and n + 8.
        if (b.id > 8) {
            for (const Ball& s : v.balls)
                if (s.id == b.id - 8) {
                    double sc, sr;
                    to_cell(l, table.width, s.position, sc, sr);
                    CHECK(colour.at(static_cast<int>(sc), static_cast<int>(sr)).style.bg == c.fg);
                }
        }
    }
}

TEST_CASE("monochrome frames use no colours", "[tui]") {
    View v = rack_view(table);
    v.called_pocket = 3;
    v.help = true;
    for (const bool utf8 : {true, false}) {
        const Grid g = draw(v, 120, 40, {0, utf8});
        for (const Cell& c : g.cells) {
            CHECK(c.style.fg == Colour::normal);
            CHECK(c.style.bg == Colour::normal);
        }
    }
}

TEST_CASE("ASCII frames hold only ASCII", "[tui]") {
    View v = rack_view(table);
    v.names[0] = "山田 Zoë";
    v.overlay = "Game over — Alice wins";
    for (const int colours : {0, 256}) {
        const Grid g = draw(v, 100, 32, {colours, false});
        for (const Cell& c : g.cells)
            for (const char ch : c.glyph)
                CHECK(static_cast<unsigned char>(ch) < 0x80);
    }
}

TEST_CASE("the cue lies opposite the aim, all round the circle", "[tui]") {
    std::vector<double> angles{0, 90, 180, 270, 45, 135, 225, 315, 0.1, 89.9, 270.1, 359.9};
    for (int k = 0; k < 360; k += 15)
        angles.push_back(k + 7.3);
    for (const bool utf8 : {true, false})
        for (const double deg : angles) {
            CAPTURE(deg, utf8);
            const View v = cue_only(deg);
            const Layout l = make_layout(table, 100, 32);
            const Grid g = render(v, l, {256, utf8}, 100, 32);
            double col, row;
            to_cell(l, table.width, v.balls[0].position, col, row);
            const double bx = col, by = row;
            double sx = 0, sy = 0, lx = 0, ly = 0;
            int cue_cells = 0, line_cells = 0;
            for (int y = 0; y < g.height; ++y)
                for (int x = 0; x < g.width; ++x) {
                    const Cell& c = g.at(x, y);
                    if (c.style.fg != Colour::aim)
                        continue;
                    // In table directions: right is +x, up is +y, a row is two columns tall.
                    const double dx = x + 0.5 - bx, dy = -2 * (y + 0.5 - by);
                    if (is_cue_glyph(c.glyph)) {
                        sx += dx, sy += dy, ++cue_cells;
                    } else {
                        lx += dx, ly += dy, ++line_cells;
                    }
                }
            REQUIRE(cue_cells >= 3);
            REQUIRE(line_cells >= 3);
            const double a = deg * M_PI / 180;
            const double cue_dir = std::atan2(-sy, -sx), line_dir = std::atan2(ly, lx);
            const auto off = [&](double d) { return std::fabs(std::remainder(d - a, 2 * M_PI)); };
            // The cue points back along the aim, the line forward.
            CHECK(off(cue_dir) < 0.2);
            CHECK(off(line_dir) < 0.05);
            // The glyph follows the direction.
            std::string want;
            const double m = std::fmod(deg, 180);
            const int sector = static_cast<int>(std::floor((m + 22.5) / 45)) % 4;
            const char* ascii[] = {"-", "/", "|", "\\"};
            const char* uni[] = {"\u2500", "\u2571", "\u2502", "\u2572"};
            want = utf8 ? uni[sector] : ascii[sector];
            for (int y = 0; y < g.height; ++y)
                for (int x = 0; x < g.width; ++x)
                    if (is_cue_glyph(g.at(x, y).glyph) && g.at(x, y).style.fg == Colour::aim)
                        CHECK(g.at(x, y).glyph == want);
        }
    // Straight up: the cue is straight below the ball, the line straight above.
    const View up = cue_only(90);
    const Layout l = make_layout(table, 100, 32);
    const Grid g = render(up, l, {256, false}, 100, 32);
    double col, row;
    to_cell(l, table.width, up.balls[0].position, col, row);
    const int bx = static_cast<int>(col), by = static_cast<int>(row);
    CHECK(g.at(bx, by + 2).glyph == "|");
    CHECK(g.at(bx, by - 2).glyph == ".");
    const Grid down = render(cue_only(270), l, {256, false}, 100, 32);
    CHECK(down.at(bx, by - 2).glyph == "|");
    CHECK(down.at(bx, by + 2).glyph == ".");
}

TEST_CASE("a tenth of a degree of aim shows on a long line at 100x32", "[tui]") {
    const double L = table.length, W = table.width;
    const Vec2 starts[] = {{0.1, 0.1},       {0.1, W / 2},   {0.1, W - 0.1},   {L / 2, 0.1},
                           {L / 2, W - 0.1}, {L - 0.1, 0.1}, {L - 0.1, W / 2}, {L - 0.1, W - 0.1}};
    int tested = 0;
    for (const bool aid : {false, true})
        for (double deg = 0; deg < 360; deg += 6.7) {
            // From whichever start gives the longest line.
            Vec2 from = starts[0];
            double longest = 0;
            for (const Vec2 s : starts) {
                Ball cue;
                cue.position = s;
                const AimPreview p = preview_shot(table, {cue}, R, s, deg);
                const double len = length(p.cue_path.back() - p.cue_path.front());
                if (len > longest)
                    longest = len, from = s;
            }
            if (longest < 1.5)
                continue;
            CAPTURE(deg, aid, from.x, from.y, longest);
            View a = cue_only(deg, from), b = cue_only(deg + 0.1, from);
            for (View* v : {&a, &b}) {
                v->show_aid = aid;
                v->cue_path = preview_shot(table, v->balls, R, from, v->aim_deg).cue_path;
            }
            int changed = 0;
            const Grid ga = draw(a, 100, 32), gb = draw(b, 100, 32);
            for (std::size_t i = 0; i < ga.cells.size(); ++i)
                changed += ga.cells[i] != gb.cells[i];
            CHECK(changed >= 1);
            ++tested;
        }
    CHECK(tested > 40);
}

TEST_CASE("lines never cover a ball", "[tui]") {
    // Aim straight through the rack with the plain aim line, and with the aid: the lines cross
    // the rack's rows, yet every ball keeps its glyph.
    for (const bool aid : {false, true})
        for (const auto& [w, h] : {std::pair{200, 60}, {100, 32}, {80, 24}})
            for (const Mode& mode : modes) {
                CAPTURE(aid, w, h, mode.name);
                View v = rack_view(table, 0.4);
                v.show_aid = aid;
                const Layout l = make_layout(table, w, h);
                const Grid g = render(v, l, mode.caps, w, h);
                const bool wide = wide_labels(l.cells_per_metre, R);
                View bare = v;
                bare.aiming = false;
                const Grid without = render(bare, l, mode.caps, w, h);
                CHECK(misplaced(g, v, l, mode.caps.utf8) == std::vector<std::string>{});
                for (const Ball& b : v.balls) {
                    const auto [x, y] = cell_at(l, table.width, b.position);
                    CHECK(g.at(x, y).glyph == without.at(x, y).glyph);
                }
                if (w != 200)
                    continue;
                // Big enough that each ball has its own cell: the one holding its centre.
                for (const Ball& b : v.balls) {
                    double col, row;
                    to_cell(l, table.width, b.position, col, row);
                    const std::string label = ball_label(b.id, mode.caps.utf8, wide);
                    const std::string& glyph =
                        g.at(static_cast<int>(col), static_cast<int>(row)).glyph;
                    CHECK(label.find(glyph) != std::string::npos);
                }
            }
}

TEST_CASE("render never writes outside the grid and never fails, at any size", "[tui]") {
    View full = rack_view(table);
    full.help = true;
    full.overlay = "A question?\nyes / no";
    full.called_pocket = 2;
    full.show_marker = true;
    full.marker = {2.0, 0.3};
    full.names[0] = "山田太郎さんのチーム名前";
    const Layout big = make_layout(table, 200, 60);
    for (const auto& [w, h] :
         {std::pair{1, 1}, {5, 3}, {39, 13}, {0, 0}, {2, 40}, {40, 14}, {41, 15}, {-3, 7}})
        for (const Mode& mode : modes) {
            CAPTURE(w, h, mode.name);
            for (const View& v : {full, rack_view(table), View{}}) {
                const Grid g = render(v, make_layout(table, w, h), mode.caps, w, h);
                CHECK(g.width == std::max(w, 0));
                CHECK(g.height == std::max(h, 0));
                CHECK(g.cells.size() == static_cast<std::size_t>(g.width * g.height));
                for (const Cell& c : g.cells)
                    CHECK(display_width(c.glyph) <= 1);
                // A layout made for a bigger screen is clipped too.
                const Grid clipped = render(v, big, mode.caps, w, h);
                CHECK(clipped.cells.size() == static_cast<std::size_t>(g.width * g.height));
            }
        }
    const Grid one = render(full, make_layout(table, 1, 1), {256, true}, 1, 1);
    CHECK(one.at(0, 0) == Cell{});
}

TEST_CASE("broken positions and sizes in a view draw nothing wrong", "[tui]") {
    View v = rack_view(table);
    const double bad[] = {NAN, INFINITY, -INFINITY, 1e300, -1e300, 1e9};
    for (const double x : bad) {
        CAPTURE(x);
        View w = v;
        w.balls[0].position = {x, 0.5};
        w.balls[3].position = {0.5, x};
        w.cue_path.push_back({x, x});
        w.object_path = {{0.5, 0.5}, {x, 0.2}};
        w.ghost = {x, 0.1};
        w.show_marker = true;
        w.marker = {x, x};
        w.aim_deg = x;
        w.power = x;
        w.speed = x;
        w.side = x;
        w.follow = x;
        w.ball_radius = std::fabs(x);
        for (const Mode& mode : modes) {
            const Grid g = draw(w, 100, 32, mode.caps);
            CHECK(g.cells.size() == 3200u);
        }
    }
}

TEST_CASE("a small terminal is asked to grow", "[tui]") {
    const Grid g = draw(rack_view(table), 39, 13);
    std::string all;
    for (const Cell& c : g.cells)
        all += c.glyph;
    CHECK(all.find("Please enlarge") != std::string::npos);
    CHECK(all.find("40x14") != std::string::npos);
    const Grid tiny = draw(rack_view(table), 5, 3);
    for (const Cell& c : tiny.cells)
        CHECK(c == Cell{});
}

TEST_CASE("ball in hand: the cue ball is red where it may not go", "[tui]") {
    View v = rack_view(table);
    v.aiming = false;
    v.placing = true;
    const Layout l = make_layout(table, 100, 32);
    double col, row;
    to_cell(l, table.width, table.head_spot(), col, row);
    const int x = static_cast<int>(col), y = static_cast<int>(row);
    CHECK(render(v, l, {256, true}, 100, 32).at(x, y).style.fg == Colour::white);
    v.placement_legal = false;
    CHECK(render(v, l, {256, true}, 100, 32).at(x, y).style.fg == Colour::red);
    CHECK(render(v, l, {0, true}, 100, 32).at(x, y).style.reverse);
}

TEST_CASE("calling a pocket labels all six and lights the called one", "[tui]") {
    View v = rack_view(table);
    const Layout l = make_layout(table, 100, 32);
    const Grid none = render(v, l, {256, true}, 100, 32);
    v.called_pocket = 4;
    const Grid called = render(v, l, {256, true}, 100, 32);
    for (int n = 1; n <= 6; ++n) {
        const PocketCells p = pocket_cells(table, l, n);
        CHECK(none.at(p.label_x, p.label_y).glyph == " ");
        const Cell& label = called.at(p.label_x, p.label_y);
        CHECK(label.glyph == std::string(1, static_cast<char>('0' + n)));
        CHECK(label.style.bg == (n == 4 ? Colour::highlight : Colour::pocket));
        for (const auto& [x, y] : p.cells)
            CHECK(called.at(x, y).style.bg == (n == 4 ? Colour::highlight : Colour::pocket));
    }
    // Pocket numbers follow the table: 1 bottom left, 3 bottom right, 4 top right, 6 top left.
    const PocketCells p1 = pocket_cells(table, l, 1), p4 = pocket_cells(table, l, 4);
    CHECK(p1.label_y > p4.label_y);
    CHECK(p1.label_x < p4.label_x);
    CHECK(pocket_at(table, l, p4.label_x, p4.label_y) == 4);
    CHECK(pocket_at(table, l, 50, 10) == 0);
}

TEST_CASE("the status rows show power, speed, mode and spin", "[tui]") {
    View v = rack_view(table);
    v.is_break = false;
    v.power = 0.5;
    v.speed = 3.4;
    v.side = 0.2;
    v.follow = -0.3;
    v.time_power = true;
    const Layout l = make_layout(table, 100, 32);
    for (const bool utf8 : {true, false}) {
        const Grid g = render(v, l, {256, utf8}, 100, 32);
        std::string first, second;
        for (int x = 0; x < g.width; ++x) {
            first += g.at(x, l.status_y).glyph;
            second += g.at(x, l.status_y + 1).glyph;
        }
        CAPTURE(first, second);
        CHECK(first.rfind("power [", 0) == 0);
        CHECK(first.find("] 3.4 m/s") != std::string::npos);
        CHECK(first.find("[ shoot ]") != std::string::npos);
        CHECK(second.rfind("spin: side +0.2 follow -0.3", 0) == 0);
        CHECK(second.find("timed") != std::string::npos);
        CHECK(g.at(7, l.status_y).style.fg == Colour::red);
        // 3.4 m/s of a scale to the break's 12 m/s: 8.5 of 30 cells; past 7 m/s, out of a
        // shot's reach, dots.
        if (!utf8)
            CHECK(first.find("[#########---------............]") != std::string::npos);
    }
}

TEST_CASE("the power bar's scale reaches the break's speed: a full break is not a full shot",
          "[tui]") {
    const auto bar = [](double speed, bool is_break, bool utf8) {
        View v = rack_view(table);
        v.is_break = is_break;
        v.power = power_from_speed(speed, is_break);
        v.speed = speed;
        const Layout l = make_layout(table, 100, 32);
        const Grid g = render(v, l, {256, utf8}, 100, 32);
        const std::string row = row_text(g, l.status_y);
        const std::size_t open = row.find('['), close = row.find(']');
        REQUIRE(close != std::string::npos);
        return row.substr(open + 1, close - open - 1);
    };
    const auto count = [](const std::string& s, const std::string& glyph) {
        int n = 0;
        for (std::size_t at = s.find(glyph); at != std::string::npos; at = s.find(glyph, at + 1))
            ++n;
        return n;
    };
    for (const bool utf8 : {true, false}) {
        CAPTURE(utf8);
        const std::string shot = bar(max_shot_speed, false, utf8);
        const std::string brk = bar(max_break_speed, true, utf8);
        CAPTURE(shot, brk);
        CHECK(shot != brk);
        const std::string full = utf8 ? "\u2588" : "#";
        // The break fills all 30 cells; the shot 7/12 of them, the rest dotted out of reach.
        CHECK(count(brk, full) == 30);
        CHECK(count(shot, full) == (utf8 ? 17 : 18));
        CHECK(count(shot, utf8 ? "\u00B7" : ".") == 12);
        // Half power of each: the break's bar is the longer, as its speed is.
        CHECK(count(bar(speed_from_power(0.5, true), true, utf8), full) >
              count(bar(speed_from_power(0.5, false), false, utf8), full));
    }
}

TEST_CASE("the spin diagram marks where the tip strikes: + side right, + follow up", "[tui]") {
    const auto marker = [](double side, double follow, int w, int h) {
        View v = rack_view(table);
        v.side = side;
        v.follow = follow;
        const Grid g = draw(v, w, h);
        const Layout l = make_layout(table, w, h);
        for (int y = l.panel_y; y < l.panel_y + l.panel_height; ++y)
            for (int x = l.panel_x; x < l.panel_x + l.panel_width; ++x)
                if (g.at(x, y).glyph == "+" && g.at(x, y).style.fg == Colour::red)
                    return std::pair{x, y};
        return std::pair{-1, -1};
    };
    for (const auto& [w, h] : {std::pair{80, 24}, {120, 24}, {200, 40}}) {
        CAPTURE(w, h);
        const auto centre = marker(0, 0, w, h);
        REQUIRE(centre.first >= 0);
        CHECK(marker(0.5, 0, w, h).first > centre.first);
        CHECK(marker(0.5, 0, w, h).second == centre.second);
        CHECK(marker(-0.5, 0, w, h).first < centre.first);
        CHECK(marker(0, 0.5, w, h).second < centre.second);
        CHECK(marker(0, -0.5, w, h).second > centre.second);
        CHECK(marker(0, -0.5, w, h).first == centre.first);
    }
}

TEST_CASE("the panel marks the shooter and shows groups, pocketed balls and the message", "[tui]") {
    View v = rack_view(table);
    v.aiming = false;
    v.shooter = 2;
    v.names[0] = "山田太郎";
    v.names[1] = "Bob";
    v.groups[0] = Group::solids;
    v.groups[1] = Group::stripes;
    for (Ball& b : v.balls)
        if (b.id == 9 || b.id == 12)
            b.state = MotionState::pocketed;
    v.message = "Bob pocketed the 9 and the 12 and shoots again.";
    for (const auto& [w, h] : {std::pair{120, 24}, {80, 24}, {100, 32}}) {
        CAPTURE(w, h);
        const Grid g = draw(v, w, h, {256, true});
        std::string all;
        for (int y = 0; y < g.height; ++y) {
            for (int x = 0; x < g.width; ++x)
                all += g.at(x, y).glyph;
            all += '\n';
        }
        CAPTURE(all);
        CHECK(all.find("▶ Bob") != std::string::npos);
        CHECK(all.find("  山田太郎") != std::string::npos);
        CHECK(all.find("solids") != std::string::npos);
        CHECK(all.find("stripes 9 12") != std::string::npos);
        CHECK(all.find("8-ball") != std::string::npos);
        CHECK(all.find("shoots") != std::string::npos);
        // A wide character fills its cell and leaves the next one empty.
        bool found = false;
        for (int y = 0; y < g.height; ++y)
            for (int x = 0; x + 1 < g.width; ++x)
                if (g.at(x, y).glyph == "山") {
                    found = true;
                    CHECK(g.at(x + 1, y).glyph.empty());
                }
        CHECK(found);
    }
}

TEST_CASE("overlays and help are boxes on top of everything", "[tui]") {
    View v = rack_view(table);
    v.overlay = "Alice wins!\nPress n for a new game.";
    Grid g = draw(v, 100, 32);
    CHECK(screen_text(g).find("Alice wins!") != std::string::npos);
    CHECK(screen_text(g).find("╭") != std::string::npos);
    v.overlay.clear();
    v.help = true;
    std::string all;
    const int pages = help_page_count(120, 40);
    for (v.help_page = 0; v.help_page < pages; ++v.help_page)
        all += screen_text(draw(v, 120, 40));
    for (const char* key : {"Left Right", "Shift+Left Right",
                            "l ",         "Up Down",
                            "Space",      "[ ]",
                            "w a s d",    "W A S D",
                            "c ",         "p ",
                            "g ",         "1-6",
                            "n ",         "x ",
                            "? ",         "q ",
                            "Mouse",      "move",
                            "drag",       "shoot",
                            "release"})
        CHECK(all.find(key) != std::string::npos);
}

namespace {

const std::pair<int, int> all_sizes[] = {{80, 24},  {100, 32}, {200, 60}, {120, 24},
                                         {200, 40}, {40, 14},  {60, 40},  {300, 90}};
const Capabilities tiers[] = {{256, true},  {8, true},  {0, true},
                              {256, false}, {8, false}, {0, false}};

View nine_ball_view() {
    View v = rack_view(table);
    v.balls = make_rack(table, PhysicsParams{}, RackType::nine_ball);
    v.game = GameType::nine_ball;
    return v;
}

View ten_ball_view() {
    View v = rack_view(table);
    v.balls = make_rack(table, PhysicsParams{}, RackType::ten_ball, 4);
    v.game = GameType::ten_ball;
    return v;
}

// The rack after the 1 went down: nothing may still read "1".
View rack_without_one() {
    View v = rack_view(table);
    for (Ball& b : v.balls)
        if (b.id == 1)
            b.state = MotionState::pocketed;
    return v;
}

} // namespace

TEST_CASE("every ball is drawn on the cell of its centre and no two numbers run together, in "
          "every tier and at every size",
          "[tui]") {
    const std::pair<const char*, View> views[] = {{"rack", rack_view(table)},
                                                  {"crowded", crowded_view(table)},
                                                  {"nine", nine_ball_view()},
                                                  {"ten", ten_ball_view()},
                                                  {"without the 1", rack_without_one()}};
    for (const auto& [name, v] : views)
        for (const auto& [w, h] : all_sizes)
            for (const Capabilities& caps : tiers) {
                CAPTURE(name, w, h, caps.colours, caps.utf8);
                const Layout l = make_layout(table, w, h);
                const Grid g = render(v, l, caps, w, h);
                CHECK(misplaced(g, v, l, caps.utf8) == std::vector<std::string>{});
                // A ball with a cell of its own and no number beside it shows its own label.
                for (const Ball& b : v.balls) {
                    if (b.state == MotionState::pocketed)
                        continue;
                    const auto [x, y] = cell_at(l, table.width, b.position);
                    bool crowded = false;
                    for (const Ball& o : v.balls)
                        if (&o != &b && o.state != MotionState::pocketed) {
                            const auto [ox, oy] = cell_at(l, table.width, o.position);
                            crowded = crowded || (oy == y && std::abs(ox - x) <= 2);
                        }
                    const bool wide = wide_labels(l.cells_per_metre, R);
                    const std::string label = ball_label(b.id, caps.utf8, wide);
                    if (!crowded && label.size() == 1)
                        CHECK(g.at(x, y).glyph == label);
                }
            }
    // Two-cell numbers where a ball is three columns across, single letters below that.
    CHECK(wide_labels(make_layout(table, 200, 60).cells_per_metre, R));
    CHECK_FALSE(wide_labels(make_layout(table, 100, 32).cells_per_metre, R));
    CHECK(ball_label(12, true, false) == "C");
    CHECK(ball_label(12, false, true) == "12");
    CHECK(ball_label(9, true, false) == "9");
}

TEST_CASE("where two numbers would touch, one gives way to a mark in its ball's style", "[tui]") {
    // The 1 and the 7 in neighbouring cells (overlapping: the renderer draws what it is
    // given): drawn first, the 1 keeps its number.
    View v = cue_only(0, {0.3, 0.3});
    v.aiming = false;
    Ball one, seven, twelve;
    one.id = 1, seven.id = 7, twelve.id = 12;
    const Layout l = make_layout(table, 100, 32);
    one.position = from_cell(l, table.width, 40, 10);
    seven.position = from_cell(l, table.width, 41, 10);
    twelve.position = from_cell(l, table.width, 42, 10);
    v.balls.insert(v.balls.end(), {seven, one, twelve});
    for (const Capabilities& caps : tiers) {
        CAPTURE(caps.colours, caps.utf8);
        const Grid g = render(v, l, caps, 100, 32);
        CHECK(g.at(40, 10).glyph == "1");
        CHECK(g.at(41, 10).glyph == ball_mark(caps.utf8));
        CHECK(g.at(41, 10).style == (caps.colours ? ball_style(7, true) : ball_style(7, false)));
        // A letter reads as no part of a number: the 12 keeps its letter beside the 7.
        CHECK(g.at(42, 10).glyph == "C");
        CHECK(misplaced(g, v, l, caps.utf8) == std::vector<std::string>{});
    }
    // Two balls in one cell: the first drawn covers the other; the cue ball is always drawn.
    Ball cue_ball = v.balls[0];
    cue_ball.position = one.position + Vec2{0.001, 0};
    v.balls = {one, cue_ball};
    const Grid g = render(v, l, {256, true}, 100, 32);
    CHECK(g.at(40, 10).glyph == "\u25CF");
}

TEST_CASE("the 8-colour tier draws the 256-colour frame: the terminal maps the roles", "[tui]") {
    for (const View& v : {rack_view(table), crowded_view(table)})
        for (const bool utf8 : {true, false})
            CHECK(draw(v, 80, 24, {8, utf8}).cells == draw(v, 80, 24, {256, utf8}).cells);
}

TEST_CASE("the legend shows the balls on the table as drawn, on one row where there is room",
          "[tui]") {
    const View v = crowded_view(table); // the 1, 5, 11 and 14 are down
    SECTION("letters with their numbers at 80x24 and 100x32") {
        for (const auto& [w, h] : {std::pair{80, 24}, {100, 32}}) {
            CAPTURE(w, h);
            const Grid g = draw(v, w, h);
            const std::string last = row_text(g, h - 1);
            CHECK(last.rfind("on table 2 3 4 6 7 8 9 A=10 C=12 D=13 F=15", 0) == 0);
            CHECK(last.find("B=11") == std::string::npos);
            CHECK(last.find("? help  q quit") != std::string::npos);
            // Each ball styled as on the table.
            const auto [ax, ay] = find_cell(g, "A=10");
            REQUIRE(ay == h - 1);
            CHECK(g.at(ax, ay).style == ball_style(10, true));
        }
    }
    SECTION("numbers at 200x60, on one row") {
        const Grid g = draw(v, 200, 60);
        CHECK(row_text(g, 59).rfind("on table 2 3 4 6 7 8 9 10 12 13 15", 0) == 0);
        CHECK(row_text(g, 59).find("? help  q quit") != std::string::npos);
    }
    SECTION("the full rack at every size") {
        for (const auto& [w, h] : all_sizes)
            for (const bool utf8 : {true, false}) {
                CAPTURE(w, h, utf8);
                const Layout l = make_layout(table, w, h);
                const Grid g = render(rack_view(table), l, {0, utf8}, w, h);
                std::string panel;
                for (int y = l.panel_y; y < l.panel_y + l.panel_height; ++y)
                    panel += row_text(g, y, l.panel_x, l.panel_x + l.panel_width) + "\n";
                CAPTURE(panel);
                const bool wide = wide_labels(l.cells_per_metre, R);
                std::size_t from = 0;
                for (int id = 1; id <= 15; ++id) {
                    const std::size_t at = panel.find(ball_label(id, utf8, wide), from);
                    CHECK(at != std::string::npos);
                    from = at == std::string::npos ? from : at;
                }
                if (l.panel_below) // one row: the last
                    CHECK(panel.substr(panel.rfind('\n', panel.size() - 2) + 1)
                              .find(ball_label(15, utf8, wide)) != std::string::npos);
            }
    }
}

TEST_CASE("the help hint shows at every size", "[tui]") {
    View placing = rack_view(table);
    placing.aiming = false;
    placing.placing = true;
    View talkative = crowded_view(table);
    talkative.message = "Bob fouled: no ball hit a cushion after the contact. Alice has ball in "
                        "hand anywhere on the table.";
    for (const View& v : {rack_view(table), crowded_view(table), placing, talkative, View{}})
        for (const auto& [w, h] : all_sizes) {
            CAPTURE(w, h);
            const Grid g = draw(v, w, h);
            CHECK(screen_text(g).find("? help") != std::string::npos);
            // The terminal never draws the bottom-right cell: nothing may need it.
            CHECK(g.at(w - 1, h - 1).glyph == " ");
        }
}

TEST_CASE("a whole group of pocketed balls and long names fit the panel", "[tui]") {
    View v = rack_view(table);
    v.aiming = false;
    v.message = "Bartholomew Jr pocketed the 15 and shoots again";
    v.names[0] = "Maximiliana";
    v.names[1] = "Bartholomew Jr";
    v.groups[0] = Group::solids;
    v.groups[1] = Group::stripes;
    v.race_to = 2;
    v.racks_won[1] = 1;
    for (Ball& b : v.balls)
        if (b.id >= 9)
            b.state = MotionState::pocketed;
    for (const auto& [w, h] : {std::pair{80, 24}, {100, 32}, {200, 60}}) {
        CAPTURE(w, h);
        const std::string all = screen_text(draw(v, w, h));
        CAPTURE(all);
        CHECK(all.find("stripes 9 10 11 12 13 14 15") != std::string::npos);
        // The names line up, so the scores and groups stand in columns.
        CHECK(all.find("Maximiliana    0  solids") != std::string::npos);
        CHECK(all.find("Bartholomew Jr 1  stripes") != std::string::npos);
    }
}

TEST_CASE("8-ball: pocketed balls are listed under the player whose group they are", "[tui]") {
    View v = rack_view(table);
    v.aiming = false;
    v.message.clear();
    const auto drop = [&](std::initializer_list<int> ids) {
        for (Ball& b : v.balls)
            if (std::find(ids.begin(), ids.end(), b.id) != ids.end())
                b.state = MotionState::pocketed;
    };
    drop({3, 11});
    // The list follows the groups (who potted them is not even in the View).
    for (const auto& [w, h] : {std::pair{80, 24}, {100, 32}, {200, 60}, {120, 24}}) {
        CAPTURE(w, h);
        v.groups[0] = v.groups[1] = Group::open;
        std::string all = screen_text(draw(v, w, h, {0, false}));
        CAPTURE(all);
        CHECK(all.find("open table") != std::string::npos);
        CHECK(all.find("pocketed 3 11") != std::string::npos);
        v.groups[0] = Group::stripes;
        v.groups[1] = Group::solids;
        all = screen_text(draw(v, w, h, {0, false}));
        CHECK(all.find("stripes 11") != std::string::npos);
        CHECK(all.find("solids 3") != std::string::npos);
        CHECK(all.find("pocketed") == std::string::npos);
        // Alice's line holds her group.
        const std::size_t alice = all.find("Alice"), stripes = all.find("stripes 11");
        const std::size_t bob = all.find("Bob");
        CHECK(alice < stripes);
        CHECK(stripes < bob);
    }
    // The 8 belongs to nobody: its own line.
    v.groups[0] = Group::stripes;
    v.groups[1] = Group::solids;
    drop({8});
    CHECK(screen_text(draw(v, 100, 32)).find("pocketed 8") != std::string::npos);
}

TEST_CASE("9-ball: one list of what has dropped, and the consecutive fouls", "[tui]") {
    View v = nine_ball_view();
    v.aiming = false;
    v.message.clear();
    for (Ball& b : v.balls)
        if (b.id == 1 || b.id == 4)
            b.state = MotionState::pocketed;
    v.fouls[0] = 1;
    v.fouls[1] = 2;
    for (const auto& [w, h] : {std::pair{80, 24}, {100, 32}, {200, 60}, {120, 24}, {40, 14}})
        for (const int colours : {256, 0}) {
            CAPTURE(w, h, colours);
            const Grid g = draw(v, w, h, {colours, true});
            const std::string all = screen_text(g);
            CAPTURE(all);
            CHECK(all.find("pocketed 1 4") != std::string::npos);
            CHECK(all.find("1 foul") != std::string::npos);
            REQUIRE(all.find("2 fouls: a third loses") != std::string::npos);
            CHECK(all.find("open table") == std::string::npos);
            // The warning stands out: highlighted, reversed without colour.
            const auto [x, y] = find_cell(g, "2 fouls");
            const Style s = g.at(x, y).style;
            CHECK(s.bold);
            CHECK((colours ? s.fg == Colour::highlight : s.reverse));
        }
    v.fouls[0] = v.fouls[1] = 0;
    CHECK(screen_text(draw(v, 100, 32)).find("foul") == std::string::npos);
}

TEST_CASE("10-ball: the title, one list of what has dropped, and the consecutive fouls",
          "[tui][ten]") {
    View v = ten_ball_view();
    v.aiming = false;
    v.message.clear();
    for (Ball& b : v.balls)
        if (b.id == 2 || b.id == 10)
            b.state = MotionState::pocketed;
    v.fouls[1] = 2;
    const std::string all = screen_text(draw(v, 100, 32));
    CAPTURE(all);
    CHECK(all.find("10-ball") != std::string::npos);
    CHECK(all.find("pocketed 2 10") != std::string::npos);
    CHECK(all.find("2 fouls: a third loses") != std::string::npos);
    CHECK(all.find("open table") == std::string::npos);
}

TEST_CASE("the called pocket is said in words", "[tui]") {
    View v = rack_view(table);
    v.called_pocket = 6;
    v.called_ball = 8;
    for (const auto& [w, h] : {std::pair{80, 24}, {100, 32}, {200, 60}, {200, 40}}) {
        CAPTURE(w, h);
        const Layout l = make_layout(table, w, h);
        const Grid g = render(v, l, {256, true}, w, h);
        // The panel's text, which at 200x40 (the side panel) wraps it.
        std::string panel;
        for (int y = l.panel_y; y < l.panel_y + l.panel_height; ++y)
            panel += row_text(g, y, l.panel_x) + "\n";
        CAPTURE(panel);
        CHECK(words(panel).find("calls the 8 in the top-left corner") != std::string::npos);
    }
    CHECK(pocket_name(1) == std::string("bottom-left corner"));
    CHECK(pocket_name(2) == std::string("bottom side pocket"));
    CHECK(pocket_name(4) == std::string("top-right corner"));
    CHECK(pocket_name(7) == std::string(""));
    v.called_ball = 0;
    v.called_pocket = 2;
    CHECK(screen_text(draw(v, 100, 32)).find("calls the bottom side pocket") != std::string::npos);
    v.called_pocket = 0;
    CHECK(screen_text(draw(v, 100, 32)).find("calls") == std::string::npos);
}

TEST_CASE("a match shows the race and the racks each player has won", "[tui]") {
    View v = crowded_view(table); // race to 5: Alice 2, Bob 1
    v.names[0] = "Player 1";
    v.names[1] = "Ann";
    for (const auto& [w, h] : {std::pair{80, 24}, {100, 32}, {200, 60}, {120, 24}, {40, 14}}) {
        CAPTURE(w, h);
        const std::string all = screen_text(draw(v, w, h));
        CAPTURE(all);
        if (w > 40) // at 40x14 the rows go to the players, the message and the legend
            CHECK(all.find("race to 5") != std::string::npos);
        // Names padded to one column, so the scores line up and never join a name.
        CHECK(all.find("Player 1 2") != std::string::npos);
        CHECK(all.find("Ann      1") != std::string::npos);
    }
    v.race_to = 0;
    const std::string single = screen_text(draw(v, 100, 32));
    CHECK(single.find("race") == std::string::npos);
    CHECK(single.find("▶ Player 1  solids") != std::string::npos);
}

TEST_CASE("the help comes in pages that fit the screen", "[tui]") {
    View v = rack_view(table);
    v.help = true;
    CHECK(help_page_count(80, 24) == 3);
    CHECK(help_page_count(200, 60) == 1);
    CHECK(help_page_count(1, 1) >= 1);
    for (const auto& [w, h] : all_sizes) {
        CAPTURE(w, h);
        const int pages = help_page_count(w, h);
        REQUIRE(pages >= 1);
        std::string shown;
        for (int page = 0; page < pages; ++page) {
            v.help_page = page;
            const std::string all = screen_text(draw(v, w, h));
            shown += all;
            CHECK(all.find(pages > 1
                               ? "page " + std::to_string(page + 1) + "/" + std::to_string(pages)
                               : "Esc closes") != std::string::npos);
            CHECK(all.find("Esc closes") != std::string::npos);
            if (page + 1 < pages)
                CHECK(all.find(w >= 60 ? "Space/PgDn more, Esc closes" : "more, Esc closes") !=
                      std::string::npos);
        }
        // Every line of the help is on some page, whole or wrapped.
        for (const std::vector<std::string>& page : help_pages(w, h))
            for (const std::string& line : page)
                CHECK(shown.find(line) != std::string::npos);
        std::size_t lines = 0;
        for (const std::string& line : box_lines(help_text(), help_width(w)))
            lines += !line.empty();
        std::size_t paged = 0;
        for (const std::vector<std::string>& page : help_pages(w, h))
            for (const std::string& line : page)
                paged += !line.empty();
        CHECK(paged == lines);
        // A page past the end shows the last one.
        v.help_page = pages + 3;
        const Grid past = draw(v, w, h);
        v.help_page = pages - 1;
        CHECK(past.cells == draw(v, w, h).cells);
    }
    // What was missing: ball in hand, calling by a click, how to close the box.
    for (const char* topic :
         {"Ball in hand", "move the cue ball", "place it there", "click a pocket", "Esc q ? Enter",
          "next page", "Practice", "take the last shot again", "next rack"})
        CHECK(help_text().find(topic) != std::string::npos);
    // In ASCII the dash is plain.
    v.help_page = 0;
    CHECK(screen_text(draw(v, 80, 24, {0, false})).find("page 1/3 - Space/PgDn more, Esc closes") !=
          std::string::npos);
}

TEST_CASE("an overlay box covers no ball", "[tui]") {
    // The push-out choice is about the ball in the middle of the table.
    View v = nine_ball_view();
    v.aiming = false;
    Ball centre;
    centre.id = 5;
    centre.position = {table.length / 2, table.width / 2};
    for (Ball& b : v.balls)
        if (b.id == 5)
            b = centre;
    v.overlay = "Bob, choose:\n1  play on\n2  Alice shoots again";
    for (const auto& [w, h] : all_sizes)
        for (const Capabilities& caps : tiers) {
            CAPTURE(w, h, caps.colours, caps.utf8);
            const Layout l = make_layout(table, w, h);
            const Grid bare = render(
                [&] {
                    View b = v;
                    b.overlay.clear();
                    return b;
                }(),
                l, caps, w, h);
            const Grid g = render(v, l, caps, w, h);
            CHECK(screen_text(g).find("Bob, choose:") != std::string::npos);
            // Every ball's cells are as they were without the box.
            REQUIRE(misplaced(bare, v, l, caps.utf8) == std::vector<std::string>{});
            for (const Ball& b : v.balls) {
                const auto [x, y] = cell_at(l, table.width, b.position);
                CHECK(is_label_glyph(bare.at(x, y).glyph, caps.utf8));
                CHECK(g.at(x, y) == bare.at(x, y));
            }
            // Nor the last row, the keys' hint (a box that fits above it keeps off it).
            for (int x = 0; x < w; ++x)
                CHECK(g.at(x, h - 1) == bare.at(x, h - 1));
        }
    // Centred when the middle is clear.
    View empty = v;
    empty.balls.clear();
    const Grid g = draw(empty, 100, 32);
    const std::string all = screen_text(g);
    const std::size_t at = all.find("Bob, choose:");
    const int y = static_cast<int>(std::count(all.begin(), all.begin() + at, '\n'));
    CHECK(y == (32 - 5) / 2 + 1);
}

TEST_CASE("in ASCII the game's dashes and quotes are plain", "[tui]") {
    View v = rack_view(table);
    v.message = "Foul: scratch \u2014 Bob has ball in hand \u201Ckitchen\u201D";
    const std::string all = screen_text(draw(v, 100, 32, {0, false}));
    CHECK(all.find("Foul: scratch - Bob has ball in hand \"kitchen\"") != std::string::npos);
    CHECK(all.find('?') == all.find("? help"));
}

TEST_CASE("the snooker table with a snooker rack renders at any size and in every mode",
          "[tui][snooker]") {
    // Here only that 22 balls and the 12 ft table draw nothing wrong; the marks and the
    // labels are tests/test_tui_snooker.cpp's.
    const PhysicsParams params = physics_for_table(TableSize::snooker);
    const Table snooker = make_table(TableSize::snooker, params.ball_radius);
    View v;
    v.table = &snooker;
    v.balls = make_rack(snooker, params, RackType::snooker, 3);
    v.ball_radius = params.ball_radius;
    v.names[0] = "Alice";
    v.names[1] = "Bob";
    v.shooter = 1;
    v.aiming = true;
    v.aim_deg = 0;
    for (const auto& [w, h] : {std::pair{80, 24}, {100, 32}, {200, 60}, {41, 15}, {5, 3}})
        for (const Mode& mode : modes) {
            CAPTURE(w, h, mode.name);
            const Grid g = render(v, make_layout(snooker, w, h), mode.caps, w, h);
            CHECK(g.cells.size() == static_cast<std::size_t>(w * h));
            for (const Cell& c : g.cells)
                CHECK(display_width(c.glyph) <= 1);
        }
}
TEST_CASE("an overlay box keeps off the last row, the keys' hint", "[tui]") {
    // Balls all over the table: no place for the box covers none, and the fewest it covers
    // were often found on the rows below the table, over the hint (a play-tester's finding:
    // the choice box's border on "? help  Tab chat  q leave").
    View v = nine_ball_view();
    v.aiming = false;
    v.balls.clear();
    int id = 1;
    for (double x = 0.1; x < table.length; x += 0.15)
        for (double y = 0.1; y < table.width; y += 0.15) {
            Ball b;
            b.id = (id++ % 15) + 1;
            b.position = {x, y};
            v.balls.push_back(b);
        }
    v.overlay = "Bob, choose:\n1  play on\n2  Alice shoots again";
    int sizes = 0;
    for (int w = 40; w <= 200; w += 7)
        for (int h = 14; h <= 60; h += 3) {
            const Layout l = make_layout(table, w, h);
            if (!l.fits)
                continue;
            ++sizes;
            CAPTURE(w, h);
            View bare_view = v;
            bare_view.overlay.clear();
            const Grid bare = render(bare_view, l, {256, true}, w, h);
            const Grid g = render(v, l, {256, true}, w, h);
            REQUIRE(screen_text(g).find("Bob, choose:") != std::string::npos);
            for (int x = 0; x < w; ++x)
                CHECK(g.at(x, h - 1) == bare.at(x, h - 1));
        }
    CHECK(sizes > 100);
}
