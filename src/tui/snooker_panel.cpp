#include "tui/snooker_panel.hpp"

#include <algorithm>
#include <termpool/text_width.hpp>

#include "tui/messages.hpp"

namespace termpool::tui {

bool snooker_panel(const View& v) {
    return game_row(v.game).scoring == Scoring::points && !v.practice;
}

std::string frames_text(const View& v) {
    if (v.best_of <= 1)
        return "";
    return "Frames " + std::to_string(std::max(0, v.racks_won[0])) + "-" +
           std::to_string(std::max(0, v.racks_won[1])) + " (best of " + std::to_string(v.best_of) +
           ")";
}

std::string high_break_text(const View& v, int player) {
    const int high = v.highest_break[player == 2 ? 1 : 0];
    return high > 0 ? "high break " + std::to_string(high) : "";
}

std::string ball_on_text(const View& v) {
    const std::string nominated = snooker_ball_name(v.nominated);
    if (v.free_ball)
        return nominated.empty() ? "free ball" : "free ball: " + nominated;
    switch (v.ball_on) {
    case BallOn::red:
        return "on red";
    case BallOn::colour:
        if (nominated.empty())
            return "on a colour";
        return v.nomination_chosen ? "nominated " + nominated : "on a colour: " + nominated;
    case BallOn::in_order:
        return v.lowest_colour ? "on " + snooker_ball_name(v.lowest_colour) : "on a colour";
    }
    return "";
}

std::vector<std::string> snooker_status_pieces(const View& v) {
    std::vector<std::string> pieces;
    if (v.current_break > 0)
        pieces.push_back("break " + std::to_string(v.current_break));
    pieces.push_back(ball_on_text(v));
    pieces.push_back(std::to_string(std::max(0, v.points_remaining)) + " left");
    return pieces;
}

std::string snooker_status(const View& v, int width, const std::string& gap) {
    // What the player is on matters most, the points left least: the pieces go in that order
    // (the break before the points left) until the rest fits; never a piece cut.
    std::vector<std::string> pieces = snooker_status_pieces(v);
    const std::string on = ball_on_text(v);
    const auto joined = [&] {
        std::string s;
        for (const std::string& piece : pieces)
            s += (s.empty() ? "" : gap) + piece;
        return s;
    };
    while (display_width(joined()) > width && pieces.size() > 1)
        pieces.erase(pieces.back() != on ? pieces.end() - 1 : pieces.begin());
    const std::string s = joined();
    return display_width(s) <= width ? s : "";
}

} // namespace termpool::tui
