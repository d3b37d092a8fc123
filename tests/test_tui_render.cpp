// The renderer: golden frames of the 8-ball rack in every display mode, the cue and aim line
// in every direction, sub-cell precision, and safety at any size.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <termpool/rack.hpp>

#include "tui/ball_style.hpp"
#include "tui/grid_dump.hpp"
#include "tui/pocket_cells.hpp"
#include "tui/text_width.hpp"
#include "tui/view.hpp"
#include "tui_frames.hpp"

using namespace termpool;
using namespace termpool::tui;
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

bool is_cue_glyph(const std::string& g) {
    return g == "-" || g == "/" || g == "|" || g == "\\" || g == "\u2500" || g == "\u2571" ||
           g == "\u2502" || g == "\u2572";
}

} // namespace

TEST_CASE("golden frames of the 8-ball rack", "[tui][golden]") {
    const bool update = std::getenv("TERMPOOL_UPDATE_GOLDEN") != nullptr &&
                        std::string(std::getenv("TERMPOOL_UPDATE_GOLDEN")) == "1";
    const View view = rack_view(table);
    for (const auto& [w, h] : {std::pair{80, 24}, {100, 32}, {200, 60}})
        for (const Mode& mode : modes) {
            const std::string path = "tests/golden/rack_" + std::to_string(w) + "x" +
                                     std::to_string(h) + "_" + mode.name + ".txt";
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
        for (const Ball& b : view.balls) {
            double col, row;
            to_cell(l, table.width, b.position, col, row);
            const Cell& c = g.at(static_cast<int>(col), static_cast<int>(row));
            CHECK(c.glyph ==
                  (b.id == 0 ? (mode.caps.utf8 ? "\u25CF" : "o") : std::to_string(b.id % 10)));
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
            CHECK(c.fg == Colour::black);
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
                const int fx = static_cast<int>(l.table_left), fy = static_cast<int>(l.table_top);
                std::vector<std::string> seen;
                for (int y = fy; y < fy + l.felt_rows; ++y)
                    for (int x = fx; x < fx + l.felt_cols; ++x) {
                        const std::string& glyph = g.at(x, y).glyph;
                        if (glyph == ball_glyph(0, mode.caps.utf8) ||
                            (glyph.size() == 1 && glyph[0] >= '0' && glyph[0] <= '9'))
                            seen.push_back(glyph);
                    }
                CHECK(seen.size() == v.balls.size());
                if (w != 200)
                    continue;
                // Big enough that each ball has its own cell: the one holding its centre.
                for (const Ball& b : v.balls) {
                    double col, row;
                    to_cell(l, table.width, b.position, col, row);
                    CHECK(g.at(static_cast<int>(col), static_cast<int>(row)).glyph ==
                          ball_glyph(b.id, mode.caps.utf8));
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
        if (!utf8)
            CHECK(first.find("[###############---------------]") != std::string::npos);
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
    v.pocketed_by[1] = {9, 12};
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

TEST_CASE("overlays and help are centred boxes on top of everything", "[tui]") {
    View v = rack_view(table);
    v.overlay = "Alice wins!\nPress n for a new game.";
    Grid g = draw(v, 100, 32);
    std::string all;
    for (const Cell& c : g.cells)
        all += c.glyph;
    CHECK(all.find("Alice wins!") != std::string::npos);
    CHECK(all.find("╭") != std::string::npos);
    v.overlay.clear();
    v.help = true;
    g = draw(v, 120, 40);
    all.clear();
    for (int y = 0; y < g.height; ++y) {
        for (int x = 0; x < g.width; ++x)
            all += g.at(x, y).glyph;
        all += '\n';
    }
    for (const char* key :
         {"Left Right", "H L",   "Up Down", "Space", "[ ]",   "w a s d", "W A S D",
          "c ",         "p ",    "g ",      "1-6",   "n ",    "x ",      "? ",
          "q ",         "Mouse", "move",    "drag",  "shoot", "release"})
        CHECK(all.find(key) != std::string::npos);
}
