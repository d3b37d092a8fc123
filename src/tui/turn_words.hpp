#pragma once
// What the message line says as a turn at the aim begins: to the player at this terminal, how
// to play it (aim and shoot, a push-out, a nomination, a kick); of another seat (the computer,
// another terminal), only what it may do.

#include <string>

#include "tui/aim.hpp"

namespace termpool::tui {

/// The facts of a turn's start that its words depend on.
struct TurnFacts {
    std::string who;                        ///< the shooter's name
    bool here = true;                       ///< the shooter plays at this terminal
    bool told = false;                      ///< verdicts of the last shot are on screen
    bool mouse = false;                     ///< the terminal reports the pointer
    bool push_out = false;                  ///< 9-ball, 10-ball: a push-out may be declared
    bool nomination = false;                ///< snooker: the shot names a colour
    bool free_ball = false;                 ///< snooker: ... and it is a free ball
    TargetLine line = TargetLine::straight; ///< how the proposed aim reaches its ball
};

/// `message` (what was said already: a verdict, a warning) with the turn's words after it.
/// Here: "Ann: aim (mouse, Left/Right), Space shoots" when nothing else is said; "u declares a
/// push-out" ("Ann: aim and shoot, or u declares a push-out" alone); "2-7 nominates a colour"
/// ("a free ball: 2-7 nominates it"); and a word on a line that is not straight ("no straight
/// line to a legal ball: a kick off one rail"). Of another seat: only "CPU (pro) may push out",
/// no keys and no how-to.
std::string turn_words(const std::string& message, const TurnFacts& facts);

} // namespace termpool::tui
