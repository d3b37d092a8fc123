#pragma once
// What the table waits for at this terminal, one type per mode with the data only it has. The
// driver's pending action decides which (App::start_turn); each mode reads its own input
// (App::on_key, in app.cpp, app_aim.cpp and app_turn.cpp) and draws its own part of the View
// (App::compose_mode, in app_view.cpp).

#include <string>
#include <termpool/vec.hpp>
#include <variant>

#include "tui/shot_show.hpp"

namespace termpool::tui {

/// The names (and the race) are asked before the first turn.
struct NamesMode {};

/// Ball in hand: the cue ball follows the keys or the pointer until it is put down.
struct PlacingMode {
    Vec2 spot; ///< where the cue ball would go
};

/// The cue is set: its state is the shooter's seat's AimState.
struct AimingMode {};

/// A shot rolls on screen; the driver has judged it already.
struct RollingMode {
    ShotShow show; ///< the balls' paths and the game as it was before the shot
};

/// A choice is owed (play on or pass back, a re-rack, a push-out's answer).
struct ChoosingMode {};

/// The rack, the game or the match is over.
struct OverMode {};

/// The mode of the table.
using TableMode =
    std::variant<NamesMode, PlacingMode, AimingMode, RollingMode, ChoosingMode, OverMode>;

} // namespace termpool::tui
