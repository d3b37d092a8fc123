// DotCanvas: clipped DDA lines and circle outlines on a Braille dot grid.

#include "tui/braille.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace termpool::tui {
namespace {

// Bit of the dot at column dx (0, 1) and row dy (0..3) inside a Braille cell (Unicode order:
// dots 1-3 and 7 on the left, 4-6 and 8 on the right).
// A threshold in [0, 1) for dot index i: the splitmix64 finaliser, well mixed for neighbouring
// indices.
double dither(int i) {
    std::uint64_t z =
        static_cast<std::uint64_t>(static_cast<std::int64_t>(i)) + 0x9E3779B97F4A7C15ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
}

constexpr std::uint8_t dot_bit[4][2] = {{0x01, 0x08}, {0x02, 0x10}, {0x04, 0x20}, {0x40, 0x80}};

// Liang-Barsky: clips the segment to [0, w] x [0, h]; false when nothing is left.
bool clip(double& x0, double& y0, double& x1, double& y1, double w, double h) {
    double t0 = 0, t1 = 1;
    const double dx = x1 - x0, dy = y1 - y0;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {x0, w - x0, y0, h - y0};
    for (int k = 0; k < 4; ++k) {
        if (p[k] == 0) {
            if (q[k] < 0)
                return false;
            continue;
        }
        const double t = q[k] / p[k];
        if (p[k] < 0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 > t1)
            return false;
    }
    const double ax = x0, ay = y0;
    x0 = ax + t0 * dx, y0 = ay + t0 * dy;
    x1 = ax + t1 * dx, y1 = ay + t1 * dy;
    return true;
}

} // namespace

DotCanvas::DotCanvas(int cols, int rows)
    : cols_(std::max(cols, 0)), rows_(std::max(rows, 0)),
      cells_(static_cast<std::size_t>(cols_) * static_cast<std::size_t>(rows_)) {}

void DotCanvas::plot(int x, int y, Colour role) {
    if (x < 0 || y < 0 || x >= 2 * cols_ || y >= 4 * rows_)
        return;
    Dots& d = cells_[index(x / 2, y / 4)];
    if (d.mask == 0)
        d.role = role;
    d.mask |= dot_bit[y % 4][x % 2];
}

void DotCanvas::line(double x0, double y0, double x1, double y1, Colour role, bool dashed) {
    if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1))
        return;
    if (!clip(x0, y0, x1, y1, 2.0 * cols_, 4.0 * rows_))
        return;
    const double dx = x1 - x0, dy = y1 - y0;
    // Step one dot at a time along the longer axis, taking the other coordinate at each dot's
    // centre line; this works the same way for every direction.
    const bool along_x = std::fabs(dx) >= std::fabs(dy);
    const double a0 = along_x ? x0 : y0, a1 = along_x ? x1 : y1;
    const double b0 = along_x ? y0 : x0,
                 slope = along_x ? (dx != 0 ? dy / dx : 0) : (dy != 0 ? dx / dy : 0);
    const int first = static_cast<int>(std::floor(a0)), last = static_cast<int>(std::floor(a1));
    const int step = last >= first ? 1 : -1;
    const double lo = std::min(a0, a1), hi = std::max(a0, a1);
    int count = 0;
    for (int i = first;; i += step, ++count) {
        const double a = std::clamp(i + 0.5, lo, hi);
        // Dithered rounding: the threshold is a hash of the absolute dot index, so it stays put
        // while the aim moves. Plain rounding keeps a horizontal or 45-degree line on the same
        // dots until its far end has moved a whole dot (7 m of line per 0.1 degree at 100x32);
        // with a threshold that varies, a shift of a fraction of a dot moves that fraction of
        // the dots. A hash rather than a regular sequence, as any regular one lines up with
        // some slope and turns back into plain rounding there. The dots' centres still average
        // out on the exact line.
        const double threshold = dither(i);
        const int j = static_cast<int>(std::floor(b0 + (a - a0) * slope - 0.5 + threshold));
        if (!dashed || count % 2 == 0) {
            if (along_x)
                plot(i, j, role);
            else
                plot(j, i, role);
        }
        if (i == last)
            break;
    }
}

void DotCanvas::circle(double cx, double cy, double radius, Colour role) {
    if (!std::isfinite(cx) || !std::isfinite(cy) || !(radius > 0) || radius > 1e4)
        return;
    const int n = std::max(8, static_cast<int>(std::ceil(2 * std::numbers::pi * radius * 2)));
    for (int k = 0; k < n; ++k) {
        const double a = 2 * std::numbers::pi * k / n;
        const double x = std::floor(cx + radius * std::cos(a));
        const double y = std::floor(cy + radius * std::sin(a));
        if (x >= 0 && y >= 0 && x < 2.0 * cols_ && y < 4.0 * rows_)
            plot(static_cast<int>(x), static_cast<int>(y), role);
    }
}

void DotCanvas::arc(double cx, double cy, double radius, double from, double to, Colour role) {
    if (!std::isfinite(cx) || !std::isfinite(cy) || !(radius > 0) || radius > 1e4 ||
        !std::isfinite(from) || !std::isfinite(to) || std::fabs(to - from) > 2 * std::numbers::pi)
        return;
    // Two samples per dot of arc, so that no dot along it is skipped.
    const int n = std::max(2, static_cast<int>(std::ceil(std::fabs(to - from) * radius * 2)));
    for (int k = 0; k <= n; ++k) {
        const double a = from + (to - from) * k / n;
        const double x = std::floor(cx + radius * std::cos(a));
        const double y = std::floor(cy - radius * std::sin(a));
        if (x >= 0 && y >= 0 && x < 2.0 * cols_ && y < 4.0 * rows_)
            plot(static_cast<int>(x), static_cast<int>(y), role);
    }
}

std::string braille_glyph(std::uint8_t mask) {
    // U+2800 + mask in UTF-8: E2, A0 + top two bits, 80 + low six bits.
    std::string g(3, '\0');
    g[0] = static_cast<char>(0xE2);
    g[1] = static_cast<char>(0xA0 | (mask >> 6));
    g[2] = static_cast<char>(0x80 | (mask & 0x3F));
    return g;
}

} // namespace termpool::tui
