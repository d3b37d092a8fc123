// dump_grid: the text and style layers of a grid.

#include "tui/grid_dump.hpp"

#include <termpool/enum_names.hpp>
#include <vector>

namespace termpool::tui {

namespace {

// The legend's words for the colour roles.
constexpr NameRow<Colour> colour_names[] = {
    {Colour::normal, "normal"},   {Colour::felt, "felt"},     {Colour::rail, "rail"},
    {Colour::cushion, "cushion"}, {Colour::pocket, "pocket"}, {Colour::white, "white"},
    {Colour::black, "black"},     {Colour::ink, "ink"},       {Colour::yellow, "yellow"},
    {Colour::blue, "blue"},       {Colour::red, "red"},       {Colour::purple, "purple"},
    {Colour::orange, "orange"},   {Colour::green, "green"},   {Colour::maroon, "maroon"},
    {Colour::brown, "brown"},     {Colour::pink, "pink"},     {Colour::aim, "aim"},
    {Colour::ghost, "ghost"},     {Colour::dim, "dim"},       {Colour::highlight, "highlight"},
};
static_assert(names_in_order(colour_names));

} // namespace

const char* colour_name(Colour c) {
    return name_of(colour_names, c);
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
