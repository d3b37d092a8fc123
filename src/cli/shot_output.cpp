#include "cli/shot_output.hpp"

#include "cli/numbers.hpp"

#include <termpool/rules_names.hpp>

namespace termpool::cli {

std::string format_event(const Event& event) {
    std::string line = "event " + format_double(event.time) + " " + event_kind_name(event.kind) +
                       " " + std::to_string(event.ball);
    // The format names the other party only where it is a ball or a pocket, not for rails.
    if (event.kind == EventKind::ball_ball || event.kind == EventKind::pocket)
        line += " " + std::to_string(event.other);
    return line + "\n";
}

std::string format_ball(const Ball& ball) {
    std::string line = "ball " + std::to_string(ball.id) + " " + format_double(ball.position.x) +
                       " " + format_double(ball.position.y);
    if (ball.state == MotionState::pocketed)
        line += " pocket " + std::to_string(ball.pocket);
    else
        line += " table";
    return line + "\n";
}

std::string format_shot(const std::vector<Event>& events, const std::vector<Ball>& balls,
                        double rest_time) {
    std::string out;
    for (const Event& e : events)
        out += format_event(e);
    for (const Ball& b : balls)
        out += format_ball(b);
    out += "rest " + format_double(rest_time) + "\n";
    return out;
}

std::string format_verdict(const Verdict& verdict) {
    std::string out = "first-contact ";
    out += verdict.first_contact < 0 ? "none" : std::to_string(verdict.first_contact);
    out += "\nfoul " + std::string(foul_name(verdict.foul)) + "\npocketed";
    for (const int id : verdict.pocketed)
        out += " " + std::to_string(id);
    // The same words as the `groups` directive, so a verdict can seed the next scenario.
    out += "\ngroups ";
    out += name_of(player1_group_names, verdict.player1_group);
    out += "\nnext " + std::to_string(verdict.next_shooter);
    out += "\nball-in-hand " + std::string(ball_in_hand_name(verdict.ball_in_hand)) + "\n";
    if (verdict.chooser != 0) {
        out += "choice";
        for (const Choice c : verdict.choices)
            out += " " + std::string(choice_name(c));
        out += "\n";
    }
    if (verdict.winner != 0)
        out += "winner " + std::to_string(verdict.winner) + " " + win_reason_name(verdict.reason) +
               "\n";
    return out;
}

} // namespace termpool::cli
