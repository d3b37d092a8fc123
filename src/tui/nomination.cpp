#include "tui/nomination.hpp"

#include <algorithm>
#include <termpool/snooker_layout.hpp>
#include <vector>

#include "tui/messages.hpp"

namespace termpool::tui {

void propose_nomination(const Game& game, AimState& aim) {
    if (!game.nomination_owed()) {
        aim.nominated = 0;
        aim.nomination_chosen = false;
        return;
    }
    if (aim.nomination_chosen)
        return;
    const int aimed = aim.preview_ball;
    if (game.snooker().free_ball) {
        // Any ball not on may be the free ball; aiming at a ball on is playing it.
        const std::vector<int> on = game.balls_on();
        aim.nominated = aimed > 0 && std::find(on.begin(), on.end(), aimed) == on.end() ? aimed : 0;
    } else {
        aim.nominated = is_snooker_colour(aimed) ? aimed : 0;
    }
}

std::optional<std::string> nomination_key(const Game& game, AimState& aim, const std::string& text,
                                          const std::string& who) {
    if (text.size() != 1 || text[0] < '0' || text[0] > '9')
        return std::nullopt;
    const int value = text[0] - '0';
    if (!game.nomination_owed())
        return "No nomination now: " + std::string(game.snooker().ball_on == BallOn::red
                                                       ? "on a red"
                                                       : "on the colours in order");
    if (value < 2 || value > 7)
        return "Nominate a colour by its value: 2 yellow, 3 green, 4 brown, 5 blue, 6 pink, "
               "7 black";
    const int id = snooker_yellow + value - 2;
    const bool on_table = std::any_of(game.balls().begin(), game.balls().end(), [&](const Ball& b) {
        return b.id == id && b.state != MotionState::pocketed;
    });
    if (!on_table)
        return "The " + snooker_ball_name(id) + " is not on the table";
    if (aim.nomination_chosen && aim.nominated == id) {
        aim.nomination_chosen = false;
        propose_nomination(game, aim);
        return std::string("Nomination: the ball aimed at");
    }
    aim.nominated = id;
    aim.nomination_chosen = true;
    return who + (game.snooker().free_ball ? " nominates the free ball: " : " nominates ") +
           snooker_ball_name(id);
}

Call nomination_call(const Game& game, const AimState& aim) {
    Call call;
    if (game.nomination_owed() && aim.nomination_chosen)
        call.ball = aim.nominated;
    return call;
}

} // namespace termpool::tui
