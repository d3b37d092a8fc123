// The first spot of the cue ball in hand: the natural spot, or the legal spot nearest it (not
// the first of the legal spots, which may be far across the table).

#include "tui/cue_ball_spot.hpp"

#include <algorithm>
#include <termpool/snooker_layout.hpp>
#include <vector>

namespace termpool::tui {

Vec2 first_cue_ball_spot(const Game& g, Vec2 head_spot) {
    Vec2 want = head_spot;
    if (g.ball_in_hand() == BallInHand::d) {
        const double r = snooker_d_radius_on(g.table());
        want = snooker_d_centre(g.table()) + Vec2{-r / 4, -r / 2};
    }
    if (g.legal_placement(want))
        return want;
    const std::vector<Vec2> spots = g.legal_placements(24);
    if (spots.empty())
        return want;
    return *std::min_element(spots.begin(), spots.end(),
                             [&](Vec2 a, Vec2 b) { return length(a - want) < length(b - want); });
}

} // namespace termpool::tui
