#include "player/stats_summary.hpp"

#include <cmath>

#include <termpool/text_width.hpp>

namespace termpool {
namespace {

constexpr int label_columns = 14; // "Break-and-runs"
constexpr int figure_columns = (stats_summary_columns - label_columns) / 2;

std::string pad_left(const std::string& s, int columns) {
    return std::string(static_cast<std::size_t>(std::max(0, columns - display_width(s))), ' ') + s;
}

// `name` in at most `columns`; a cut one ends in an ellipsis, so that two cut names side by
// side still read as two.
std::string fit_name(const std::string& name, int columns) {
    if (display_width(name) <= columns)
        return name;
    return truncate_to_width(name, columns - 1) + "\u2026";
}

std::string pad_right(const std::string& s, int columns) {
    return s + std::string(static_cast<std::size_t>(std::max(0, columns - display_width(s))), ' ');
}

} // namespace

std::string pot_success_text(const PlayerStats& s) {
    const auto success = pot_success(s);
    if (!success)
        return "-";
    return std::to_string(static_cast<int>(std::lround(*success * 100))) + "%";
}

std::string stats_summary(const std::string names[2], const PlayerStats s[2]) {
    // A space before each figure column keeps the columns apart, so a name gets one less.
    std::string text = std::string(label_columns, ' ');
    for (int p = 0; p < 2; ++p)
        text += pad_left(fit_name(names[p], figure_columns - 1), figure_columns);
    auto row = [&](const char* label, const std::string& a, const std::string& b) {
        text += "\n" + pad_right(label, label_columns) + pad_left(a, figure_columns) +
                pad_left(b, figure_columns);
    };
    auto counts = [&](const char* label, int PlayerStats::*field) {
        row(label, std::to_string(s[0].*field), std::to_string(s[1].*field));
    };
    counts("Racks won", &PlayerStats::racks_won);
    counts("Balls potted", &PlayerStats::balls_potted);
    row("Pot success", pot_success_text(s[0]), pot_success_text(s[1]));
    counts("Fouls", &PlayerStats::fouls);
    counts("Longest run", &PlayerStats::longest_run);
    counts("Break-and-runs", &PlayerStats::break_and_runs);
    return text;
}

} // namespace termpool
