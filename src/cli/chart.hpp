#pragma once
// Line charts in the terminal, for `termpool experiment`: Braille dots where UTF-8 is
// available, plain characters otherwise.

#include <string>
#include <vector>

namespace termpool::cli {

/// One series of (x, y) points.
struct Series {
    std::string name;                              ///< legend
    char mark = '*';                               ///< ASCII mark of this series
    std::vector<std::pair<double, double>> points; ///< ascending x
};

/// A chart `width` x `height` characters of all series over their common range, with axes
/// labelled; `utf8` chooses Braille (each character 2x4 dots) over ASCII marks.
std::string draw_chart(const std::vector<Series>& series, int width, int height, bool utf8,
                       const std::string& x_label, const std::string& y_label);

} // namespace termpool::cli
