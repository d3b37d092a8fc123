// Snooker's figures are counted in frames and points: a rack, a run of balls and a
// break-and-run mean nothing there. The frame's breaks come from the referee's score sheet.

#include "tui/game_figures.hpp"

#include <algorithm>
#include <termpool/text_width.hpp>

#include "player/stats_summary.hpp"

namespace termpool::tui {
namespace {

constexpr int label_columns = 14;
constexpr int figure_columns = (stats_summary_columns - label_columns) / 2;
// A break of this many points or more.
constexpr int century = 100;

std::string padded_left(const std::string& s, int columns) {
    return std::string(static_cast<std::size_t>(std::max(0, columns - display_width(s))), ' ') + s;
}

std::string padded_right(const std::string& s, int columns) {
    return s + std::string(static_cast<std::size_t>(std::max(0, columns - display_width(s))), ' ');
}

// A name in a figure column, an ellipsis where it is cut (two cut names still read as two).
std::string column_name(const std::string& name) {
    const int room = figure_columns - 1;
    if (display_width(name) <= room)
        return name;
    return truncate_to_width(name, room - 1) + "\u2026";
}

std::string snooker_figures(const Match& match) {
    const PlayerStats s[2] = {match.tally().of(1), match.tally().of(2)};
    const SnookerState& sheet = match.game().snooker();
    std::string text = std::string(label_columns, ' ');
    for (int p = 1; p <= 2; ++p)
        text += padded_left(column_name(match.name(p)), figure_columns);
    const auto row = [&](const char* label, const std::string& a, const std::string& b) {
        text += "\n" + padded_right(label, label_columns) + padded_left(a, figure_columns) +
                padded_left(b, figure_columns);
    };
    const auto counts = [&](const char* label, int one, int two) {
        row(label, std::to_string(one), std::to_string(two));
    };
    counts("Frames won", s[0].racks_won, s[1].racks_won);
    counts("Frame score", sheet.scores[0], sheet.scores[1]);
    counts("Highest break", sheet.highest_break[0], sheet.highest_break[1]);
    // One frame holds at most one century a player (147 points, a free ball's few more).
    counts("Centuries", sheet.highest_break[0] >= century ? 1 : 0,
           sheet.highest_break[1] >= century ? 1 : 0);
    counts("Balls potted", s[0].balls_potted, s[1].balls_potted);
    row("Pot success", pot_success_text(s[0]), pot_success_text(s[1]));
    counts("Fouls", s[0].fouls, s[1].fouls);
    return text;
}

} // namespace

std::string game_figures_text(const Match& match) {
    if (match.game().type() == GameType::snooker)
        return snooker_figures(match);
    const PlayerStats figures[2] = {match.tally().of(1), match.tally().of(2)};
    return stats_summary(match.record().names, figures);
}

} // namespace termpool::tui
