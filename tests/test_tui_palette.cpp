// The colour roles the terminal maps to: every ball stands apart from the cloth, and the
// green 6 by a clear margin from the felt and the cushion.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "tui/ball_style.hpp"
#include "tui/terminal.hpp"

using namespace termpool::tui;

namespace {

struct Rgb {
    double r, g, b;
};

// The colour xterm shows for a 256-colour index: 16 system colours, the 6x6x6 cube, 24 greys.
Rgb xterm_rgb(int index) {
    if (index < 16) {
        constexpr int system[16][3] = {
            {0, 0, 0},       {205, 0, 0},   {0, 205, 0},   {205, 205, 0},
            {0, 0, 238},     {205, 0, 205}, {0, 205, 205}, {229, 229, 229},
            {127, 127, 127}, {255, 0, 0},   {0, 255, 0},   {255, 255, 0},
            {92, 92, 255},   {255, 0, 255}, {0, 255, 255}, {255, 255, 255}};
        return {double(system[index][0]), double(system[index][1]), double(system[index][2])};
    }
    if (index < 232) {
        constexpr int level[6] = {0, 95, 135, 175, 215, 255};
        const int i = index - 16;
        return {double(level[i / 36]), double(level[i / 6 % 6]), double(level[i % 6])};
    }
    const double grey = 8 + 10 * (index - 232);
    return {grey, grey, grey};
}

// WCAG relative luminance and contrast ratio (1: the same, 21: black on white).
double luminance(const Rgb& c) {
    auto linear = [](double v) {
        v /= 255;
        return v <= 0.03928 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
    };
    return 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b);
}

double contrast(int a, int b) {
    const double la = luminance(xterm_rgb(a)), lb = luminance(xterm_rgb(b));
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

// How far apart two colours are in RGB (0..441).
double distance(int a, int b) {
    const Rgb x = xterm_rgb(a), y = xterm_rgb(b);
    return std::hypot(x.r - y.r, x.g - y.g, x.b - y.b);
}

} // namespace

TEST_CASE("every ball colour differs from the felt", "[tui][palette]") {
    const Palette felt = palette(Colour::felt);
    for (int id = 0; id <= 15; ++id) {
        INFO("ball " << id);
        const Palette ball = palette(ball_colour(id));
        CHECK(ball.c256 != felt.c256);
        CHECK(distance(ball.c256, felt.c256) > 100); // 34, the old 6, was 40 from the felt
    }
    // With 8 colours the green is the felt's own: the 6 needs another.
    CHECK(palette(ball_colour(6)).c8 != felt.c8);
}

TEST_CASE("the 6 stands clear of the felt and the cushion in 256 colours", "[tui][palette]") {
    const int six = palette(ball_colour(6)).c256;
    CHECK(contrast(six, palette(Colour::felt).c256) >= 3.0);
    CHECK(contrast(six, palette(Colour::cushion).c256) >= 3.0);
    // It carries black digits (ball_style): they must read on it.
    CHECK(contrast(six, palette(Colour::black).c256) >= 7.0);
    // Still a green: the green channel leads.
    const Rgb rgb = xterm_rgb(six);
    CHECK(rgb.g > rgb.r);
    CHECK(rgb.g > rgb.b);
}

TEST_CASE("snooker's colours differ from the felt and from each other in 256 colours",
          "[tui][palette][snooker]") {
    const Palette felt = palette(Colour::felt);
    std::vector<int> seen;
    for (int id = 0; id <= 21; ++id) {
        INFO("snooker ball " << id);
        const Palette ball = palette(ball_colour(id, BallSet::snooker));
        CHECK(ball.c8 != felt.c8);
        CHECK(distance(ball.c256, felt.c256) > 100);
        if (id == 0 || id > 15)
            seen.push_back(ball.c256);
        // The digits on it read: black, or white on the black.
        const Style s = ball_style(id, true, BallSet::snooker);
        if (id > 0)
            CHECK(contrast(palette(s.fg).c256, ball.c256) >= 4.0);
    }
    for (std::size_t i = 0; i < seen.size(); ++i)
        for (std::size_t j = i + 1; j < seen.size(); ++j)
            CHECK(distance(seen[i], seen[j]) > 60);
}
