// dump_grid: the text and style layers of a grid.

#include "tui/grid_dump.hpp"

#include <vector>

namespace termpool::tui {

const char* colour_name(Colour c) {
    switch (c) {
    case Colour::normal:
        return "normal";
    case Colour::felt:
        return "felt";
    case Colour::rail:
        return "rail";
    case Colour::cushion:
        return "cushion";
    case Colour::pocket:
        return "pocket";
    case Colour::white:
        return "white";
    case Colour::black:
        return "black";
    case Colour::ink:
        return "ink";
    case Colour::yellow:
        return "yellow";
    case Colour::blue:
        return "blue";
    case Colour::red:
        return "red";
    case Colour::purple:
        return "purple";
    case Colour::orange:
        return "orange";
    case Colour::green:
        return "green";
    case Colour::maroon:
        return "maroon";
    case Colour::brown:
        return "brown";
    case Colour::pink:
        return "pink";
    case Colour::aim:
        return "aim";
    case Colour::ghost:
        return "ghost";
    case Colour::dim:
        return "dim";
    case Colour::highlight:
        return "highlight";
    }
    return "?";
}

std::string dump_grid(const Grid& grid) {
    static const std::string letters =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    std::vector<Style> styles;
    auto letter = [&](const Style& s) {
        std::size_t k = 0;
        while (k < styles.size() && !(styles[k] == s))
            ++k;
        if (k == styles.size())
            styles.push_back(s);
        return k < letters.size() ? letters[k] : '?';
    };
    std::string out =
        "grid " + std::to_string(grid.width) + "x" + std::to_string(grid.height) + "\n";
    for (int y = 0; y < grid.height; ++y) {
        out += '|';
        for (int x = 0; x < grid.width; ++x)
            out += grid.at(x, y).glyph;
        out += "|\n";
    }
    out += "styles\n";
    for (int y = 0; y < grid.height; ++y) {
        out += '|';
        for (int x = 0; x < grid.width; ++x)
            out += letter(grid.at(x, y).style);
        out += "|\n";
    }
    out += "legend\n";
    for (std::size_t k = 0; k < styles.size(); ++k) {
        const Style& s = styles[k];
        out += k < letters.size() ? letters[k] : '?';
        out += std::string(" fg=") + colour_name(s.fg) + " bg=" + colour_name(s.bg);
        if (s.bold)
            out += " bold";
        if (s.reverse)
            out += " reverse";
        out += '\n';
    }
    return out;
}

} // namespace termpool::tui
