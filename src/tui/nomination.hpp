#pragma once
// Snooker's nomination at the table: after a red, or with a free ball, the shot names its ball
// on. The aimed ball is proposed, as a pool call proposes its pocket, until the player names
// another with its value (2 yellow .. 7 black); the same key again goes back to the proposal.

#include <optional>
#include <string>
#include <termpool/rules.hpp>

#include "tui/aim_state.hpp"

namespace termpool::tui {

/// Sets `aim`'s nomination for the shot at hand: none when `game` owes none, the player's own
/// when named, else the aimed ball (a colour; with a free ball any ball not on).
void propose_nomination(const Game& game, AimState& aim);
/// A digit typed while aiming in snooker: names a colour by its value, or says why not. The
/// message for the player, or nothing when `text` is not a digit. `who` is the shooter's name.
std::optional<std::string> nomination_key(const Game& game, AimState& aim, const std::string& text,
                                          const std::string& who);
/// The shot's call in snooker: the colour (or free ball) the player named, else none, and the
/// referee takes the ball hit first, which is the aimed ball proposed.
Call nomination_call(const Game& game, const AimState& aim);

} // namespace termpool::tui
