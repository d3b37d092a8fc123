// The racks drawn true: every ball on the cell of its centre, the 9 in the middle of the
// 9-ball diamond, the 10-ball's apex on the foot spot with the spot's dot under it, in every
// display tier; the spot shows when no ball covers it.
#include <catch2/catch.hpp>
#include <cstdint>
#include <string>
#include <termpool/params.hpp>
#include <termpool/rack.hpp>
#include <vector>

#include "ball_cells.hpp"
#include "tui/ball_style.hpp"
#include "tui/view.hpp"

using namespace termpool;
using namespace termpool::tui;
using termpool::test::cell_at;
using termpool::test::glyphs_of;
using termpool::test::misdrawn_rack;

namespace {

const Table table = make_table(TableSize::nine_foot);

View rack_of(RackType type, std::uint64_t seed) {
    View v;
    v.table = &table;
    v.balls = make_rack(table, PhysicsParams{}, type, seed);
    v.game = type == RackType::nine_ball ? GameType::nine_ball : GameType::ten_ball;
    return v;
}

const Capabilities tiers[] = {{256, true}, {0, true}, {256, false}, {0, false}};

} // namespace

TEST_CASE("the 9-ball and 10-ball racks are drawn true, in every tier", "[tui][rack]") {
    for (const RackType type : {RackType::nine_ball, RackType::ten_ball})
        for (const std::uint64_t seed : {1, 2, 3, 17, 1000})
            for (const auto& [w, h] : {std::pair{80, 24}, {100, 32}, {120, 40}, {200, 60}})
                for (const Capabilities& caps : tiers) {
                    CAPTURE(static_cast<int>(type), seed, w, h, caps.colours, caps.utf8);
                    const View v = rack_of(type, game_rack_seed(seed, 0));
                    const Layout l = make_layout(table, w, h);
                    const Grid g = render(v, l, caps, w, h);
                    const bool wide = wide_labels(l.cells_per_metre, v.ball_radius);
                    CHECK(misdrawn_rack(glyphs_of(g), v.balls, l, table, type,
                                        {caps.utf8, wide, BallSet::pool}) ==
                          std::vector<std::string>{});
                }
}

TEST_CASE("the foot spot's dot shows unless a ball covers the spot", "[tui][rack]") {
    for (const bool utf8 : {true, false}) {
        const std::string dot = utf8 ? "\u00B7" : ".";
        const Layout l = make_layout(table, 100, 32);
        const auto [x, y] = cell_at(l, table.width, table.foot_spot());
        View v = rack_of(RackType::ten_ball, 5);
        CHECK(render(v, l, {256, utf8}, 100, 32).at(x, y).glyph == "1");
        // The 1 a little off the spot, still over it: still no dot, and the 1 on its own cell.
        for (Ball& b : v.balls)
            if (b.id == 1)
                b.position = table.foot_spot() + Vec2{-0.02, 0.01};
        const Grid g = render(v, l, {256, utf8}, 100, 32);
        const auto one = cell_at(l, table.width, table.foot_spot() + Vec2{-0.02, 0.01});
        CHECK(g.at(one.first, one.second).glyph == "1");
        CHECK(g.at(x, y).glyph != dot);
        // The rack gone: the dot.
        v.balls.clear();
        CHECK(render(v, l, {256, utf8}, 100, 32).at(x, y).glyph == dot);
    }
}
