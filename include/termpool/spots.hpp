#pragma once
/// \file
/// Where a ball may be put down by hand: free spots, the ball in the way, and a ball set at
/// rest on a spot. The referee (ball in hand, re-spotting) and practice share these.

#include <optional>
#include <termpool/ball.hpp>
#include <termpool/table.hpp>
#include <vector>

namespace termpool {

/// The id of a ball on the table (not pocketed, not `except_id`) that a ball of radius `R`
/// centred at `p` would overlap, or -1 when there is none.
int ball_touching(const std::vector<Ball>& balls, Vec2 p, double R, int except_id);

/// The first point on the long string (y = `from.y`) at which ball `id` touches no other ball:
/// from `from` towards the foot rail in steps of 0.5 mm, then from `from` back towards the
/// head rail (the rule for a re-spotted ball). Nothing when the whole line is taken.
std::optional<Vec2> free_spot_on_string(const Table& table, const std::vector<Ball>& balls,
                                        Vec2 from, double R, int id);

/// `ball` at rest at `p`: no velocity, no spin, on the table; its id and mass stay.
void set_at_rest(Ball& ball, Vec2 p);

} // namespace termpool
