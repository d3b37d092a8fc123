// What a terminal receives from the game's drawing, measured through a pty as `termpool bench
// --render` measures it: the count is real (nothing for an unchanged frame, a few bytes for one
// cell, thousands for a new screen), the terminal then shows exactly the frame (a terminal
// emulated from the bytes, after every frame of a break), and a break stays within its bytes.
// Bytes are deterministic for a given terminfo entry, so nothing here is timed.
#include <catch2/catch.hpp>
#include <set>
#include <string>
#include <vector>

#include "tui/bench_render.hpp"
#include "tui/blank_cells.hpp"
#include "tui/break_scene.hpp"
#include "tui/render_figures.hpp"
#include "tui/terminal.hpp"
#include "vt_screen.hpp"

using namespace termpool::tui;
using termpool::test::VtCell;
using termpool::test::VtScreen;

namespace {

// A capture that worked, or a failure that says what is missing (the terminfo entry's package).
PtyCapture captured(int width, int height, int frames, const std::function<Grid(int)>& frame) {
    PtyCapture capture = capture_through_pty(width, height, frames, frame);
    INFO(capture.error);
    REQUIRE(capture.error.empty());
    REQUIRE(capture.sent.size() == static_cast<std::size_t>(frames));
    return capture;
}

// A screen of text: row y holds letters starting at 'a' + y, on the cloth's colour.
Grid text_grid(int width, int height, char shift) {
    Grid grid(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            Cell& c = grid.at(x, y);
            c.glyph = std::string(1, static_cast<char>('a' + (x + y + shift) % 26));
            c.style = {Colour::white, (x + y + shift) % 2 ? Colour::felt : Colour::rail, false};
        }
    return grid;
}

// The colour index a role shows with 256 colours.
int colour_index(Colour c) {
    return palette(c).c256;
}

// Where the emulated terminal does not show what `grid` holds: "" when it shows it all. The
// bottom-right cell is never written (it would scroll some terminals); a blank on a coloured
// background shows only that background, however it was sent.
std::string difference(const VtScreen& screen, const Grid& grid) {
    for (int y = 0; y < grid.height; ++y)
        for (int x = 0; x < grid.width; ++x) {
            if (y == grid.height - 1 && x == grid.width - 1)
                continue;
            const Cell& want = grid.at(x, y);
            const VtCell& got = screen.at(x, y);
            const std::string glyph = got.glyph == no_break_space ? " " : got.glyph;
            const int got_bg = got.reverse ? got.fg : got.bg;
            const int got_fg = got.reverse ? got.bg : got.fg;
            const int want_bg = colour_index(want.style.reverse ? want.style.fg : want.style.bg);
            const int want_fg = colour_index(want.style.reverse ? want.style.bg : want.style.fg);
            const bool blank = want.glyph == " ";
            const bool same = glyph == want.glyph && got_bg == want_bg &&
                              (blank || (got_fg == want_fg && got.bold == want.style.bold));
            if (!same)
                return "cell " + std::to_string(x) + "," + std::to_string(y) + ": want '" +
                       want.glyph + "', shown '" + got.glyph + "' fg " + std::to_string(got_fg) +
                       " bg " + std::to_string(got_bg) + (got.bold ? " bold" : "");
        }
    return "";
}

} // namespace

TEST_CASE("bytes through a pty: nothing for an unchanged frame, few for one cell, many for all",
          "[tui][render]") {
    constexpr int width = 40, height = 12;
    std::vector<Grid> frames = {text_grid(width, height, 0), text_grid(width, height, 0)};
    Grid one_cell = frames[0];
    one_cell.at(17, 5).glyph = "Z";
    frames.push_back(one_cell);
    frames.push_back(text_grid(width, height, 1));
    const PtyCapture capture = captured(width, height, static_cast<int>(frames.size()),
                                        [&](int i) { return frames[static_cast<std::size_t>(i)]; });

    // The first frame: curses' start and every cell.
    CHECK(capture.sent[0].size() > static_cast<std::size_t>(width * height));
    CHECK(capture.sent[1].empty());
    // One cell: a move, its colours and the letter.
    CHECK(capture.sent[2].find('Z') != std::string::npos);
    CHECK(capture.sent[2].size() < 64);
    // Every cell changed: at least a byte each.
    CHECK(capture.sent[3].size() > static_cast<std::size_t>(width * height));

    VtScreen screen(width, height);
    for (std::size_t i = 0; i < frames.size(); ++i) {
        INFO("frame " << i);
        REQUIRE(screen.feed(capture.sent[i]));
        CHECK(difference(screen, frames[i]) == "");
    }
}

TEST_CASE("a terminfo entry that is not there is named, with the package that has it",
          "[tui][render]") {
    const PtyCapture capture = capture_through_pty(
        40, 12, 1, [](int) { return Grid(40, 12); }, "termpool-no-such-term");
    CHECK(capture.sent.empty());
    CHECK(capture.error.find("termpool-no-such-term") != std::string::npos);
    CHECK(capture.error.find("ncurses-base") != std::string::npos);
}

TEST_CASE("a break through a pty: the terminal shows every frame as drawn", "[tui][render]") {
    const BreakScene scene;
    for (const auto& [width, height] : {std::pair{80, 24}, {100, 32}, {200, 60}}) {
        INFO(width << "x" << height);
        const PtyCapture capture = captured(width, height, scene.frames(),
                                            [&](int i) { return scene.grid(i, width, height); });
        VtScreen screen(width, height);
        int shown = 0;
        for (int i = 0; i < scene.frames(); ++i) {
            INFO("frame " << i);
            REQUIRE(screen.feed(capture.sent[static_cast<std::size_t>(i)]));
            const std::string wrong = difference(screen, scene.grid(i, width, height));
            CHECK(wrong == "");
            if (!wrong.empty())
                break;
            ++shown;
        }
        CHECK(shown == scene.frames());
    }
}

TEST_CASE("no two rows of cloth are sent alike", "[tui][render]") {
    // curses takes rows of the same characters for moved rows and scrolls them; the signature
    // column keeps every row of cloth its own.
    const BreakScene scene;
    for (const auto& [width, height] : {std::pair{80, 24}, {100, 32}, {200, 60}})
        for (const int frame : {0, 1, 30, scene.frames() - 1}) {
            INFO(width << "x" << height << " frame " << frame);
            const Grid grid = scene.grid(frame, width, height);
            std::set<std::string> rows;
            int cloth_rows = 0;
            for (int y = 0; y < height; ++y) {
                const int signature = signature_column(grid, y);
                if (signature < 0)
                    continue;
                ++cloth_rows;
                CHECK(coloured_blank(grid.at(signature, y)));
                std::string row;
                for (int x = 0; x < width; ++x)
                    row += x == signature ? no_break_space : grid.at(x, y).glyph;
                CHECK(rows.insert(row).second);
            }
            CHECK(cloth_rows > height / 2);
        }
}

TEST_CASE("coloured blanks: spaces on a background of their own, not reversed", "[tui][render]") {
    CHECK(coloured_blank({" ", {Colour::normal, Colour::felt}}));
    CHECK(coloured_blank({" ", {Colour::white, Colour::rail, true}}));
    CHECK_FALSE(coloured_blank({" ", {}}));
    CHECK_FALSE(coloured_blank({"x", {Colour::normal, Colour::felt}}));
    CHECK_FALSE(coloured_blank({" ", {Colour::white, Colour::felt, false, true}}));
    CHECK(signature_column(Grid(3, 3), 1) == -1);
    CHECK(signature_column(Grid(3, 3), 7) == -1);
}

TEST_CASE("a break's bytes per frame through a pty stay within bounds", "[tui][render]") {
    // xterm-256color, 60 frames a second: at 100x32 at most 150 bytes a frame on average and
    // 400 at the 95th percentile, at 200x60 at most 300 on average (README, "Over SSH").
    struct Bound {
        int width, height;
        double mean;
        long p95;
    };
    for (const Bound b : {Bound{80, 24, 120, 360}, Bound{100, 32, 150, 400}, {200, 60, 300, 620}}) {
        INFO(b.width << "x" << b.height);
        const BreakScene scene;
        const BreakBytes bytes =
            break_figures(captured(b.width, b.height, scene.frames(),
                                   [&](int i) { return scene.grid(i, b.width, b.height); }));
        INFO("mean " << bytes.mean << " p95 " << bytes.p95 << " max " << bytes.max);
        CHECK(bytes.frames == scene.frames() - 1);
        CHECK(bytes.mean <= b.mean);
        CHECK(bytes.p95 <= b.p95);
        // Still a measurement: the aiming screen is thousands of bytes, the break hundreds.
        CHECK(bytes.aim_frame > 4000);
        CHECK(bytes.max > 300);
    }
}
