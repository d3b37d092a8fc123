// The close-up in tmux, as a player uses it: z opens the inset over the table with the cue
// ball, the ball it will meet and the contact point; ',' turns the aim a hundredth of a degree
// and the inset shows it (the aim and the cut it names, and its drawing); '.' turns it back;
// z closes it. The help names the keys.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <string>
#include <vector>

#include "ball_cells.hpp"
#include "tmux_session.hpp"

using tmux_session::ScratchDir;
using tmux_session::Tmux;

namespace {

// The inset's rows on a pane's text (border included), found by its top edge; empty if none.
std::vector<std::string> inset_rows(const std::string& screen) {
    const termpool::test::Glyphs g = termpool::test::glyphs_of(screen);
    for (std::size_t y = 0; y < g.size(); ++y)
        for (std::size_t x = 0; x + 1 < g[y].size(); ++x) {
            if (g[y][x] != "\u250C")
                continue;
            std::string top;
            std::size_t right = x;
            while (right < g[y].size() && g[y][right] != "\u2510")
                top += g[y][right++];
            if (top.find("close-up") == std::string::npos)
                continue;
            std::vector<std::string> rows{top};
            for (std::size_t r = y + 1; r < g.size() && x < g[r].size(); ++r) {
                std::string row;
                for (std::size_t k = x; k <= right && k < g[r].size(); ++k)
                    row += g[r][k];
                rows.push_back(row);
                if (g[r][x] == "\u2514")
                    break;
            }
            return rows;
        }
    return {};
}

// The number after `word` in the inset's rows ("aim 123.45°"), or -1.
double figure(const std::vector<std::string>& rows, const std::string& word) {
    for (const std::string& row : rows)
        if (const std::size_t at = row.find(word + " "); at != std::string::npos)
            return std::atof(row.c_str() + at + word.size() + 1);
    return -1;
}

bool inside(const std::vector<std::string>& rows, const std::string& text) {
    for (std::size_t i = 1; i + 1 < rows.size(); ++i) // the inner rows
        if (rows[i].find(text) != std::string::npos)
            return true;
    return false;
}

} // namespace

TEST_CASE("the close-up in tmux: z shows the contact, a 0.01-degree step shows in it",
          "[tui][e2e][closeup]") {
    ScratchDir dir("termpool-test");
    Tmux t;
    t.start(tmux_session::game_command(dir, "--game 9ball --player1 Ann --player2 Bob --seed 3"),
            100, 32);
    REQUIRE(t.wait_for_text("place the cue ball"));
    t.keys("Enter");
    REQUIRE(t.wait_for_text("[ shoot ]"));
    CHECK(inset_rows(t.screen()).empty());

    t.keys("z");
    REQUIRE(t.wait_for([](const std::string& s) { return !inset_rows(s).empty(); }));
    const std::vector<std::string> before = inset_rows(t.screen());
    CAPTURE(before);
    // The cue ball, the 1 it meets on the break, the contact point, the cut and the aim.
    CHECK(inside(before, "\u25CF"));
    CHECK(inside(before, "1"));
    CHECK(inside(before, "+"));
    const double aim = figure(before, "aim"), cut = figure(before, "cut");
    CHECK(aim >= 0);
    CHECK(cut >= 0);

    // A hundredth of a degree: the aim it names and the inset change.
    t.keys(",");
    REQUIRE(t.wait_for([&](const std::string& s) { return inset_rows(s) != before; }));
    const std::vector<std::string> turned = inset_rows(t.screen());
    CAPTURE(turned);
    CHECK(figure(turned, "aim") == Approx(aim + 0.01).margin(1e-6));
    CHECK(figure(turned, "cut") != Approx(cut).margin(1e-6));
    // And back.
    t.keys(".");
    CHECK(t.wait_for([&](const std::string& s) { return inset_rows(s) == before; }));

    // z closes it.
    t.keys("z");
    CHECK(t.wait_for([](const std::string& s) { return inset_rows(s).empty(); }));

    // The help names the keys.
    t.keys("?");
    REQUIRE(t.wait_for_text("0.1 degree; , . 0.01 degree"));
    CHECK(t.wait_for_text("close-up of the contact"));
}
