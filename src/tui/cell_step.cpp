#include "tui/cell_step.hpp"

#include <termpool/snooker_layout.hpp>

#include "tui/terminal.hpp"

namespace termpool::tui {

bool step_spot(Vec2& spot, int key, const std::string& text, const Layout& layout,
               const Table& table, double ball_radius, bool keep_in_d) {
    if (!layout.fits)
        return false; // no cells to step by while "please enlarge" shows
    const double step = 1.0 / layout.cells_per_metre, row = 1.0 / layout.rows_per_metre;
    Vec2 by;
    if (key == key_left)
        by = {-step, 0};
    else if (key == key_right)
        by = {step, 0};
    else if (key == key_up || text == "k")
        by = {0, row};
    else if (key == key_down || text == "j")
        by = {0, -row};
    else
        return false;
    const Vec2 stepped = step_on_table(table, spot, by, ball_radius);
    // The D is small: the keys keep a ball in hand there inside it (the pointer may leave it,
    // and is told why the ball cannot go there).
    if (!keep_in_d || !in_snooker_d(table, spot) || in_snooker_d(table, stepped))
        spot = stepped;
    return true;
}

} // namespace termpool::tui
