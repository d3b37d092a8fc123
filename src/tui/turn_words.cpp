#include "tui/turn_words.hpp"

namespace termpool::tui {
namespace {

// How the proposed aim reaches a ball it cannot see straight.
std::string line_words(TargetLine line) {
    switch (line) {
    case TargetLine::kick:
        return "no straight line to a legal ball: a kick off one rail";
    case TargetLine::uncertain_kick:
        return "no straight line to a legal ball: a kick off one rail that may not reach it";
    default:
        return "no clear line to a legal ball";
    }
}

// `message` and `more`, "; " between them when both say something.
std::string then(const std::string& message, const std::string& more) {
    return message.empty() ? more : message + "; " + more;
}

} // namespace

std::string turn_words(const std::string& message, const TurnFacts& f) {
    // Another seat's turn: the keys are not theirs to press here; the options are described.
    if (!f.here)
        return f.push_out ? then(message, f.who + " may push out") : message;
    std::string m = message;
    if (f.push_out) {
        const std::string hint = "u declares a push-out";
        m = !m.empty() ? m + "; " + hint : !f.told ? f.who + ": aim and shoot, or " + hint : hint;
    } else if (m.empty() && !f.told) {
        // Short enough for the smallest panel; the help has the rest.
        m = f.who + ": aim (" + (f.mouse ? "mouse, " : "") + "Left/Right), Space shoots";
    }
    if (f.nomination)
        m += (m.empty() ? f.who + ": " : "; ") +
             std::string(f.free_ball ? "a free ball: 2-7 nominates it" : "2-7 nominates a colour");
    // The proposed aim cannot reach the ball straight: say so before Space is pressed.
    if (f.line != TargetLine::straight)
        m = then(m, line_words(f.line));
    return m;
}

} // namespace termpool::tui
