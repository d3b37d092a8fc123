#pragma once
// The call of the shot at the table, as the panel says it and as the shot makes it: one answer
// for both, so that what the player reads before the shot is what the record holds after it.

#include <functional>
#include <termpool/rules.hpp>
#include <vector>

#include "tui/aim_state.hpp"

namespace termpool::tui {

/// What the shot as set calls, and what the panel says of it.
struct CallShown {
    ShotCall call;       ///< the call the shot makes (before Game::call_as_taken; snooker's
                         ///< nomination is nomination_call's)
    int first_ball = -1; ///< the ball the cue ball meets first (off one rail at most), -1 none
    int off_ball = 0;    ///< a combination: the ball met first when the call names another
    int foul_ball = 0;   ///< the ball met first when the shooter may not hit it first, else 0
};

/// The call of the shot `aim` sets up. Someone else's shot being shown (`aim.given_call`) calls
/// what it called. Otherwise: a safety when called; else the ball the cue ball meets first
/// into the chosen pocket, when `calls_pocket` says a shot at it names one and the shooter may
/// hit it first (it is in `legal`; in snooker a colour the player nominated narrows `legal` to
/// itself). A ball the shooter may not hit first is named as `foul_ball` and never called.
CallShown shot_call(const AimState& aim, const std::vector<int>& legal,
                    const std::function<bool(int ball)>& calls_pocket);

} // namespace termpool::tui
