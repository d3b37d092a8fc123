#pragma once
// A ball moved by the keys, a cell at a time (ball in hand, practice's ball being moved).

#include <string>
#include <termpool/table.hpp>

#include "tui/view.hpp"

namespace termpool::tui {

/// Moves `spot` one cell for an arrow key (or j/k down/up); false for another key. The ball stays
/// where it may be put down (a pocket's mouth included); `keep_in_d` keeps a ball already in the
/// snooker D inside it.
bool step_spot(Vec2& spot, int key, const std::string& text, const Layout& layout,
               const Table& table, double ball_radius, bool keep_in_d);

} // namespace termpool::tui
