#include "player/stats_summary.hpp"

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

std::string stats_summary(StatsKind kind, const std::string names[2], const BoxFigures f[2]) {
    // A space before each figure column keeps the columns apart, so a name gets one less.
    std::string text = std::string(label_columns, ' ');
    for (int p = 0; p < 2; ++p)
        text += pad_left(fit_name(names[p], figure_columns - 1), figure_columns);
    for (const StatsBoxRow& row : stats_figures(kind).box)
        text += "\n" + pad_right(row.label, label_columns) +
                pad_left(row.figure(f[0]), figure_columns) +
                pad_left(row.figure(f[1]), figure_columns);
    return text;
}

std::string stats_summary(const std::string names[2], const StatsTally& tally) {
    const BoxFigures f[2] = {{tally.of(1), tally.frame_score(1)},
                             {tally.of(2), tally.frame_score(2)}};
    return stats_summary(tally.kind(), names, f);
}

} // namespace termpool
