#pragma once
// The referees of the standard games, as the registry's rows make them (game_registry.cpp).

#include <memory>
#include <termpool/referee.hpp>

namespace termpool {

/// 8-ball, WPA rules (eight_ball.cpp).
std::unique_ptr<Referee> make_eight_ball_referee();
/// 8-ball, bar rules (eight_ball.cpp).
std::unique_ptr<Referee> make_bar_eight_ball_referee();
/// 9-ball, WPA rules (rotation.cpp).
std::unique_ptr<Referee> make_nine_ball_referee();
/// 10-ball, WPA rules (rotation.cpp).
std::unique_ptr<Referee> make_ten_ball_referee();
/// Snooker, WPBSA rules (snooker.cpp).
std::unique_ptr<Referee> make_snooker_referee();

} // namespace termpool
