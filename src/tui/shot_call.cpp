#include "tui/shot_call.hpp"

#include <algorithm>

namespace termpool::tui {

CallShown shot_call(const AimState& aim, const std::vector<int>& legal,
                    const std::function<bool(int ball)>& calls_pocket) {
    CallShown out;
    out.first_ball = aim.preview_ball;
    if (aim.given_call) {
        out.call = *aim.given_call;
        const int called = out.call.call.ball;
        if (called > 0 && out.first_ball > 0 && out.first_ball != called)
            out.off_ball = out.first_ball;
        return out;
    }
    out.call.push_out = aim.push_out;
    if (out.first_ball > 0) {
        // A nominated colour (or free ball) is the one ball that may be hit first.
        const bool nominated = aim.nomination_chosen && aim.nominated > 0;
        const bool allowed =
            nominated ? out.first_ball == aim.nominated
                      : std::find(legal.begin(), legal.end(), out.first_ball) != legal.end();
        if (!allowed)
            out.foul_ball = out.first_ball;
    }
    if (aim.safety)
        out.call.call.safety = true;
    else if (out.first_ball > 0 && out.foul_ball == 0 && aim.called_pocket != 0 &&
             calls_pocket(out.first_ball))
        out.call.call = {out.first_ball, aim.called_pocket, false};
    return out;
}

} // namespace termpool::tui
