// The racks in tmux, as a player sees them at the break: the 9-ball and 10-ball racks at
// 100x32 and 80x24 with every ball on the cell of its centre (computed from the rack the
// game's seed makes, through the game's own layout), the 9 in the middle of the diamond and
// the 10-ball's apex on the foot spot with no spot dot beside it.
#include <catch2/catch.hpp>
#include <cstdint>
#include <string>
#include <termpool/params.hpp>
#include <termpool/rack.hpp>
#include <vector>

#include "ball_cells.hpp"
#include "tmux_session.hpp"
#include "tui/view.hpp"

using namespace termpool;
using tmux_session::ScratchDir;
using tmux_session::Tmux;

TEST_CASE("the 9-ball and 10-ball racks in tmux: each ball on its own cell", "[tui][e2e][rack]") {
    const Table table = make_table(TableSize::nine_foot);
    struct Case {
        const char* game;
        RackType type;
        int width, height;
        std::uint64_t seed;
        bool ascii;
    };
    const Case cases[] = {
        {"9ball", RackType::nine_ball, 100, 32, 1, false},
        {"9ball", RackType::nine_ball, 100, 32, 7, false},
        {"9ball", RackType::nine_ball, 80, 24, 1, false},
        {"9ball", RackType::nine_ball, 80, 24, 7, true},
        {"10ball", RackType::ten_ball, 100, 32, 1, false},
        {"10ball", RackType::ten_ball, 100, 32, 7, false},
        {"10ball", RackType::ten_ball, 80, 24, 1, false},
        {"10ball", RackType::ten_ball, 80, 24, 7, true},
    };
    for (const Case& c : cases) {
        CAPTURE(c.game, c.width, c.height, c.seed, c.ascii);
        // A game of its own each time: a fresh state directory, and a server whose end waits
        // for the game to have saved and gone.
        ScratchDir dir("termpool-test");
        Tmux t;
        const std::string args = std::string("--game ") + c.game + " --player1 Ann --player2 Bob" +
                                 " --seed " + std::to_string(c.seed) + (c.ascii ? " --ascii" : "");
        t.start(tmux_session::game_command(dir, args), c.width, c.height);
        REQUIRE(t.wait_for_text("place the cue ball"));
        const std::string screen = t.screen();
        CAPTURE(screen);
        const tui::Layout l = tui::make_layout(table, c.width, c.height);
        const std::vector<Ball> rack =
            make_rack(table, PhysicsParams{}, c.type, game_rack_seed(c.seed, 0));
        CHECK(test::misdrawn_rack(test::glyphs_of(screen), rack, l, table, c.type,
                                  {!c.ascii, false, tui::BallSet::pool}) ==
              std::vector<std::string>{});
    }
}
