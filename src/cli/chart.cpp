#include "cli/chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace termpool::cli {
namespace {

// Braille: dot (col, row) of a 2x4 cell sets this bit of U+2800 + bits.
constexpr int braille_bit[4][2] = {{0x01, 0x08}, {0x02, 0x10}, {0x04, 0x20}, {0x40, 0x80}};

std::string utf8(unsigned code) {
    std::string s;
    s += static_cast<char>(0xE0 | (code >> 12));
    s += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    s += static_cast<char>(0x80 | (code & 0x3F));
    return s;
}

std::string label(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3g", v);
    return b;
}

} // namespace

std::string draw_chart(const std::vector<Series>& series, int width, int height, bool use_utf8,
                       const std::string& x_label, const std::string& y_label) {
    double x_max = 0, y_max = 0;
    for (const Series& s : series)
        for (const auto& [x, y] : s.points) {
            x_max = std::max(x_max, x);
            y_max = std::max(y_max, y);
        }
    if (x_max <= 0 || y_max <= 0 || width < 4 || height < 2)
        return "";
    const int sub_x = use_utf8 ? 2 : 1, sub_y = use_utf8 ? 4 : 1;
    std::vector<std::vector<int>> dots(static_cast<std::size_t>(height),
                                       std::vector<int>(static_cast<std::size_t>(width), 0));
    std::vector<std::string> ascii(static_cast<std::size_t>(height), std::string(width, ' '));
    for (const Series& s : series) {
        for (const auto& [x, y] : s.points) {
            const int px =
                std::clamp(static_cast<int>(x / x_max * (width * sub_x - 1)), 0, width * sub_x - 1);
            const int py = std::clamp(static_cast<int>((1 - y / y_max) * (height * sub_y - 1)), 0,
                                      height * sub_y - 1);
            const auto row = static_cast<std::size_t>(py / sub_y);
            const auto col = static_cast<std::size_t>(px / sub_x);
            if (use_utf8)
                dots[row][col] |= braille_bit[py % 4][px % 2];
            else
                ascii[row][col] = s.mark;
        }
    }
    std::string out = y_label + "\n";
    const std::string top = label(y_max);
    const std::size_t margin = top.size() + 1;
    for (int r = 0; r < height; ++r) {
        const std::string axis = r == 0 ? top : r == height - 1 ? "0" : "";
        out += std::string(margin - axis.size(), ' ') + axis + "|";
        for (int c = 0; c < width; ++c) {
            const auto row = static_cast<std::size_t>(r), col = static_cast<std::size_t>(c);
            if (use_utf8)
                out += dots[row][col] ? utf8(0x2800u + static_cast<unsigned>(dots[row][col])) : " ";
            else
                out += ascii[row][col];
        }
        out += "\n";
    }
    out +=
        std::string(margin, ' ') + "+" + std::string(static_cast<std::size_t>(width), '-') + "\n";
    const std::string right = label(x_max) + " " + x_label;
    out +=
        std::string(margin, ' ') + "0" +
        std::string(std::max<std::size_t>(1, static_cast<std::size_t>(width) - right.size()), ' ') +
        right + "\n";
    return out;
}

} // namespace termpool::cli
