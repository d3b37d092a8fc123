// The panel: the game and the match's race, both players (the one to shoot marked) with the
// racks they have won and, in 8-ball, their group with its balls pocketed so far (9-ball: their
// consecutive fouls), the balls pocketed outside any group, the message, the called pocket in
// words, the spin diagram with the cue's elevation, a legend of the balls on the table and the help
// hint. Beside the table it is a column; below it (narrow terminals) players, message and spin
// diagram sit side by side above a row holding the legend and the hint.

#include <algorithm>
#include <climits>
#include <cmath>
#include <iterator>
#include <string>
#include <termpool/game_registry.hpp>
#include <termpool/setup.hpp>
#include <termpool/snooker_layout.hpp>
#include <vector>

#include "tui/aim.hpp"
#include "tui/ball_style.hpp"
#include "tui/draw.hpp"
#include "tui/messages.hpp"
#include "tui/pocket_cells.hpp"
#include "tui/snooker_panel.hpp"
#include <termpool/text_width.hpp>

namespace termpool::tui {
namespace {

const Style dim{Colour::dim};
const Style bold{Colour::normal, Colour::normal, true};
const Style mark{Colour::highlight, Colour::normal, true};

// A line of differently styled pieces.
struct Piece {
    std::string text;
    Style style;
};
using Line = std::vector<Piece>;

int width_of(const Line& line) {
    int w = 0;
    for (const Piece& piece : line)
        w += display_width(piece.text);
    return w;
}

// The words of `text` that fit `width` columns whole (none when the first does not).
std::string whole_words(const std::string& text, int width) {
    if (display_width(text) <= width)
        return text;
    std::size_t end = 0;
    for (std::size_t space = text.find(' '); space != std::string::npos;
         space = text.find(' ', space + 1)) {
        if (display_width(std::string_view(text).substr(0, space)) > width)
            break;
        end = space;
    }
    return text.substr(0, end);
}

// `line` in `width` columns without a word cut: the last pieces, the least telling, go until
// the rest fits, and a first piece still too wide keeps the words of it that fit.
Line fitted(Line line, int width) {
    while (line.size() > 1 && width_of(line) > width)
        line.pop_back();
    if (!line.empty() && width_of(line) > width)
        line.front().text = whole_words(line.front().text, width);
    return line;
}

int draw_line(Painter& p, int x, int y, const Line& whole, int width) {
    int used = 0;
    for (const Piece& piece : fitted(whole, width))
        if (used < width)
            used += p.text(x + used, y, piece.text, piece.style, width - used);
    return used;
}

// `text` wrapped to `width`, each line in `style`.
std::vector<Line> wrapped(const std::string& text, int width, Style style) {
    std::vector<Line> lines;
    if (!text.empty())
        for (std::string& line : wrap_to_width(text, width))
            lines.push_back({{std::move(line), style}});
    return lines;
}

// `pieces` joined two spaces apart, as many to a row as fit `width`: a piece is never split
// (one wider than a row keeps the words that fit).
std::vector<Line> piece_rows(const std::vector<std::string>& pieces, int width, Style style) {
    std::vector<Line> rows;
    std::string row;
    for (const std::string& piece : pieces) {
        if (!row.empty() && display_width(row) + 2 + display_width(piece) <= width) {
            row += "  " + piece;
            continue;
        }
        if (!row.empty())
            rows.push_back({{row, style}});
        row = whole_words(piece, width);
    }
    if (!row.empty())
        rows.push_back({{row, style}});
    return rows;
}

// The last of `lines` kept when the rest had no room: it ends in an ellipsis after a whole
// word, so that the player sees there is more (the log, `l`, has the message whole).
void mark_cut(Line& line, int width, bool utf8) {
    if (line.empty())
        return;
    const std::string more = utf8 ? "\u2026" : "...";
    std::string& text = line.back().text;
    while (!text.empty() && display_width(text) + display_width(more) > width) {
        const std::size_t space = text.find_last_of(' ');
        text.erase(space == std::string::npos ? 0 : space);
    }
    text += more;
}

bool in_group(int id, Group g) {
    return (g == Group::solids && id >= 1 && id <= 7) ||
           (g == Group::stripes && id >= 9 && id <= 15);
}

// Practice has one player at the table.
int players(const View& v) {
    return v.practice ? 1 : 2;
}

// The object balls that have dropped, in order, that `keep` accepts.
template <class Keep> std::string pocketed(const View& v, Keep keep) {
    std::vector<int> ids;
    for (const Ball& b : v.balls)
        if (b.id > 0 && b.state == MotionState::pocketed && keep(b.id))
            ids.push_back(b.id);
    std::sort(ids.begin(), ids.end());
    const bool snooker = ball_set(v) == BallSet::snooker;
    std::string s;
    for (const int id : ids)
        s += " " + (snooker ? ball_label(id, false, false, BallSet::snooker) : std::to_string(id));
    return s;
}

// "solids 1 3 4" (the player's group and what of it has dropped), "open table"; in 9-ball and
// 10-ball the consecutive fouls, the second one as a warning.
Piece player_detail(const Frame& f, int player) {
    const View& v = f.view;
    if (v.practice)
        return {"", {}}; // no referee: no groups, no fouls
    const PlayerLine line = game_row(v.game).panel.player;
    if (line == PlayerLine::highest_break)
        return {high_break_text(v, player), dim};
    if (line == PlayerLine::fouls_in_a_row) {
        const int fouls = std::max(0, v.fouls[player - 1]);
        if (fouls == 0)
            return {"", dim};
        if (fouls == 2)
            return {"2 fouls: a third loses",
                    {Colour::highlight, Colour::normal, true, !f.paint.colour()}};
        return {std::to_string(fouls) + (fouls == 1 ? " foul" : " fouls"), dim};
    }
    const Group g = v.groups[player - 1];
    if (g == Group::open)
        return {"open table", dim};
    return {(g == Group::solids ? "solids" : "stripes") +
                pocketed(v, [&](int id) { return in_group(id, g); }),
            dim};
}

// "pocketed 3 11": in 9-ball and 10-ball all that has dropped, in 8-ball what belongs to nobody's
// group (all of it on an open table, the 8). Empty when there is none.
std::string loose_balls(const View& v) {
    const PocketedLine line = game_row(v.game).panel.pocketed;
    if (line == PocketedLine::none)
        return ""; // snooker's colours come back, its reds are counted in the legend
    const std::string ids = pocketed(v, [&](int id) {
        return line == PocketedLine::all ||
               !(in_group(id, v.groups[0]) || in_group(id, v.groups[1]));
    });
    return ids.empty() ? "" : "pocketed" + ids;
}

// "8-ball, race to 5"; with `title` false just "race to 5" (empty without a race).
Line header(const View& v, bool title) {
    Line line;
    if (snooker_panel(v)) {
        // "snooker  Frames 1-0 (best of 5)"
        const std::string frames = frames_text(v);
        if (title)
            line.push_back({game_title(v.game), bold});
        if (!frames.empty())
            line.push_back({title ? "  " + frames : frames, bold});
        return line;
    }
    const std::string race = v.race_to > 0 ? "race to " + std::to_string(v.race_to) : "";
    if (title)
        line.push_back({std::string(game_title(v.game)) + (v.practice ? " practice" : ""), bold});
    if (!race.empty())
        line.push_back({title ? ", " + race : race, title ? bold : dim});
    return line;
}

// "the 4", or in snooker "the pink".
std::string ball_words(const View& v, int id) {
    return "the " + (ball_set(v) == BallSet::snooker ? snooker_ball_name(id) : std::to_string(id));
}

// What the shot calls: "calls the 8 in the top-left corner", a combination as one call ("calls
// the 10 in the top-left corner, off the 5"), "calls a safety"; before any of it, a warning
// when the aim meets first a ball it may not ("hitting the 4 first is a foul").
std::string call_text(const View& v) {
    if (v.foul_ball > 0)
        return "hitting " + ball_words(v, v.foul_ball) + " first is a foul";
    if (v.called_safety)
        return "calls a safety";
    if (v.called_pocket < 1 || v.called_pocket > 6)
        return "";
    const std::string ball = v.called_ball > 0 ? ball_words(v, v.called_ball) + " in " : "";
    const std::string off =
        v.called_ball > 0 && v.call_off_ball > 0 ? ", off " + ball_words(v, v.call_off_ball) : "";
    return "calls " + ball + "the " + pocket_name(v.called_pocket) + off;
}

// The call in the highlight; the warning of a foul in red.
Style call_style(const View& v) {
    return v.foul_ball > 0 ? Style{Colour::red, Colour::normal, true} : mark;
}

// The widest a name is shown (what a player may type; the hall's may be longer).
constexpr int max_name_cols = 20;

// Marker, name and, in a race, the racks won, the names padded to one column so that the
// scores line up: "▶ Ann  2".
Line name_line(const Frame& f, int player, int width) {
    const View& v = f.view;
    const bool shooting = v.shooter == player;
    // Snooker shows the points of the frame (the frames are in the header), padded to the
    // wider of the two so that they line up.
    const bool points = snooker_panel(v);
    const bool race = v.race_to > 0 || points;
    const auto figure = [&](int p) {
        return std::max(0, points ? v.scores[p - 1] : v.racks_won[p - 1]);
    };
    const int figure_w = static_cast<int>(
        points ? std::max(std::to_string(figure(1)).size(), std::to_string(figure(2)).size())
               : std::to_string(figure(player)).size());
    const int score_w = race ? 1 + figure_w : 0;
    int name_w = 0;
    for (const std::string& n : v.names)
        name_w = std::max(name_w, std::min(display_width(n), max_name_cols));
    name_w = std::max(1, std::min(name_w, width - 2 - score_w));
    // A name too long is cut visibly, with an ellipsis: a word cut short would read as another.
    std::string name = v.names[player - 1];
    if (display_width(name) > name_w)
        name = truncate_to_width(name, name_w - 1) + "\u2026";
    Line line{{shooting ? (f.paint.utf8() ? "\u25B6 " : "> ") : "  ", mark}};
    name += std::string(static_cast<std::size_t>(std::max(0, name_w - display_width(name))), ' ');
    line.push_back({name, shooting ? mark : Style{}});
    if (race) {
        std::string n = std::to_string(figure(player));
        n.insert(0, static_cast<std::size_t>(std::max(0, figure_w - static_cast<int>(n.size()))),
                 ' ');
        line.push_back({" " + n, bold});
    }
    return line;
}

// The legend's forms, most telling first: with the "on table" label, with "=10" after each
// letter, or with one "A-F=10-15" key at the end.
struct LegendForm {
    bool label, numbers, key;
};
constexpr LegendForm legend_forms[] = {{true, true, false},  {false, true, false},
                                       {true, false, true},  {false, false, true},
                                       {true, false, false}, {false, false, false}};

// The balls on the table, each drawn as on the table, in `form`, wrapped to `width`: returns
// the rows needed (INT_MAX when a piece is wider than a row), drawing at (x, y) if asked.
int lay_out_legend(const Frame& f, const std::vector<int>& ids, LegendForm form, int x, int y,
                   int width, bool draw) {
    const bool wide = labels_wide(f);
    std::vector<Line> tokens;
    if (form.label)
        tokens.push_back({{"on table", dim}});
    bool letters = false;
    const BallSet set = ball_set(f.view);
    if (set == BallSet::snooker) {
        // The reds are alike: one "1" with how many there are ("1x15"), then the colours.
        const auto reds = std::count_if(ids.begin(), ids.end(), is_snooker_red);
        if (reds > 0) {
            Line t{{ball_label(snooker_first_red, f.paint.utf8(), wide, set),
                    ball_style(snooker_first_red, f.paint.colour(), set)}};
            if (reds > 1)
                t.push_back({"x" + std::to_string(reds), dim});
            tokens.push_back(t);
        }
    }
    for (const int id : ids) {
        if (set == BallSet::snooker && is_snooker_red(id))
            continue;
        Line t{{ball_label(id, f.paint.utf8(), wide, set), ball_style(id, f.paint.colour(), set)}};
        if (set == BallSet::pool && !wide && id >= 10) {
            letters = true;
            if (form.numbers)
                t.push_back({"=" + std::to_string(id), dim});
        }
        tokens.push_back(t);
    }
    if (form.key && letters)
        tokens.push_back({{"A-F=10-15", dim}});
    int row = 0, col = 0;
    for (const Line& t : tokens) {
        const int w = width_of(t);
        if (w > width)
            return INT_MAX;
        if (col > 0 && col + 1 + w > width)
            ++row, col = 0;
        else if (col > 0)
            ++col;
        if (draw)
            draw_line(f.paint, x + col, y + row, t, w);
        col += w;
    }
    return row + 1;
}

std::vector<int> on_table(const View& v) {
    std::vector<int> ids;
    for (const Ball& b : v.balls)
        if (b.id > 0 && b.state != MotionState::pocketed)
            ids.push_back(b.id);
    std::sort(ids.begin(), ids.end());
    return ids;
}

// The most telling legend form that fits `max_rows`; drawn only when one fits whole (a cut
// legend would say balls are gone). Returns the rows used.
int draw_legend(const Frame& f, int x, int y, int width, int max_rows) {
    const std::vector<int> ids = on_table(f.view);
    if (ids.empty() || max_rows <= 0 || width <= 0)
        return 0;
    for (const LegendForm form : legend_forms) {
        const int rows = lay_out_legend(f, ids, form, x, y, width, false);
        if (rows <= max_rows)
            return lay_out_legend(f, ids, form, x, y, width, true);
    }
    return 0;
}

// Rows of the smallest legend at `width` (0 when none fits or nothing is on the table).
int legend_rows(const Frame& f, int width) {
    const std::vector<int> ids = on_table(f.view);
    if (ids.empty() || width <= 0)
        return 0;
    const LegendForm smallest = legend_forms[std::size(legend_forms) - 1];
    const int rows = lay_out_legend(f, ids, smallest, 0, 0, width, false);
    return rows == INT_MAX ? 0 : rows;
}

// The last lines of the chat that fit in `rows` at `width`, oldest first. A line cut short
// keeps its start (who said it) and ends in an ellipsis: nothing looks whole that is not.
std::vector<Line> chat_tail(const View& v, int width, int rows, bool utf8) {
    std::vector<Line> tail;
    for (auto it = v.chat.rbegin(); it != v.chat.rend() && rows > 0; ++it) {
        std::vector<Line> lines = wrapped(*it, width, dim);
        if (static_cast<int>(lines.size()) > rows) {
            lines.resize(static_cast<std::size_t>(rows));
            mark_cut(lines.back(), width, utf8);
        }
        rows -= static_cast<int>(lines.size());
        tail.insert(tail.begin(), lines.begin(), lines.end());
    }
    return tail;
}

// The hint at the panel's foot, longest first; at a hall table q leaves it and Tab chats.
std::vector<std::string> hints(const View& v) {
    if (v.hall)
        return {"? help  Tab chat  q leave", "? help  q leave", "? help"};
    return {"? help  q quit", "? help"};
}

// The longest hint that fits `width` (the shortest when none does).
std::string hint_for(const View& v, int width) {
    const std::vector<std::string> all = hints(v);
    for (const std::string& hint : all)
        if (display_width(hint) <= width)
            return hint;
    return all.back();
}

// The cue ball's face with a '+' where the tip will strike; the outermost cells are the
// +-0.5 R limit. Corners are left out so that the face reads as round.
void draw_spin_face(const Frame& f, int x, int y, int w, int h) {
    const View& v = f.view;
    Painter& p = f.paint;
    const bool colour = p.colour();
    const Style face{Colour::dim, Colour::white};
    const std::string dot = colour ? " " : (p.utf8() ? "\u00B7" : ".");
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            const bool corner = (r == 0 || r == h - 1) && (c == 0 || c == w - 1);
            if (!corner)
                p.put(x + c, y + r, dot, face);
        }
    const int cx = x + w / 2, cy = y + h / 2;
    p.put(cx, cy, p.utf8() ? "\u00B7" : ".", face);
    const auto offset = [](double value, int half) {
        const double u = std::isfinite(value) ? std::clamp(value / max_spin, -1.0, 1.0) : 0.0;
        return static_cast<int>(std::lround(u * half));
    };
    const int mx = cx + offset(v.side, w / 2), my = cy - offset(v.follow, h / 2);
    p.put(mx, my, "+", {Colour::red, Colour::white, true, !colour});
}

void draw_side_panel(const Frame& f) {
    const View& v = f.view;
    const Layout& l = f.layout;
    Painter& p = f.paint;
    const int x = l.panel_x + 1, width = l.panel_width - 1;
    int y = l.panel_y;
    const int end = l.panel_y + l.panel_height, hint_row = end - 1;
    // The hint has the last row and the legend, at its smallest, the rows above it.
    const int limit = hint_row - legend_rows(f, width);
    auto room = [&](int rows) { return y + rows <= limit; };
    auto put_lines = [&](const std::vector<Line>& lines) {
        for (const Line& line : lines)
            if (room(1))
                draw_line(p, x, y++, line, width);
    };

    const Line full = header(v, true);
    if (width_of(full) <= width)
        put_lines({full});
    else // "8-ball, bar rules" and the race on a line of its own
        put_lines({{{game_title(v.game), bold}}, header(v, false)});
    ++y;
    for (int player = 1; player <= players(v); ++player) {
        put_lines({name_line(f, player, width)});
        // The indent apart, so that a reversed warning does not reverse it.
        put_lines({{{"  ", {}}, player_detail(f, player)}});
    }
    put_lines(wrapped(loose_balls(v), width, dim));
    if (snooker_panel(v))
        put_lines(piece_rows(snooker_status_pieces(v), width, mark));
    ++y;
    // The message matters most after the players.
    if (!v.message.empty()) {
        std::vector<Line> message = wrapped(v.message, width, {});
        const int fits = std::max(0, limit - y);
        if (fits > 0 && fits < static_cast<int>(message.size())) {
            message.resize(static_cast<std::size_t>(fits));
            mark_cut(message.back(), width, p.utf8());
        }
        put_lines(message);
        ++y;
    }
    const std::string call = call_text(v);
    if (!call.empty()) {
        put_lines(wrapped(call, width, call_style(v)));
        ++y;
    }
    if (v.aiming && !v.placing) {
        const int h = room(6) && limit - y >= 12 ? 5 : 3, w = h == 5 ? 9 : 5;
        // Four lines beside the face: "spin", side, follow and the cue's elevation; the small
        // face's elevation line is one row below it.
        const int top = h / 2 - 1, rows = std::max(h, top + 4);
        if (room(rows)) {
            draw_spin_face(f, x + 1, y, w, h);
            const int tx = x + w + 3, tw = width - w - 3;
            p.text(tx, y + top, "spin", dim, tw);
            p.text(tx, y + top + 1, "side " + format_offset(v.side), {}, tw);
            p.text(tx, y + top + 2, "follow " + format_offset(v.follow), {}, tw);
            p.text(tx, y + top + 3, format_elevation(v.elevation_deg, p.utf8()),
                   elevation_style(v, p), tw);
            y += room(rows + 1) ? rows + 1 : rows;
        }
    }
    y = std::min(y, limit);
    // The chat has what the legend at its smallest leaves, under a blank row.
    if (!v.chat.empty() && limit - y >= 2) {
        ++y;
        put_lines(chat_tail(v, width, limit - y, p.utf8()));
    }
    y = std::min(y, limit);
    draw_legend(f, x, y, width, hint_row - y);
    if (hint_row >= l.panel_y)
        p.text(x, hint_row, hint_for(v, width), dim, width);
}

// The bottom row of the panel below the table: the legend, and the hint at the right end.
void draw_legend_row(const Frame& f, int x, int y, int width) {
    const std::vector<int> ids = on_table(f.view);
    for (const LegendForm form : legend_forms)
        for (const std::string& hint : hints(f.view)) {
            const int hint_w = display_width(hint);
            if (ids.empty() || lay_out_legend(f, ids, form, x, y, width - hint_w - 2, false) != 1)
                continue;
            lay_out_legend(f, ids, form, x, y, width - hint_w - 2, true);
            f.paint.text(x + width - hint_w, y, hint, dim);
            return;
        }
    // Nothing on the table, or no room for both: the hint alone.
    const std::string hint = hint_for(f.view, width);
    f.paint.text(x + std::max(0, width - display_width(hint)), y, hint, dim, width);
}

void draw_below_panel(const Frame& f) {
    const View& v = f.view;
    const Layout& l = f.layout;
    Painter& p = f.paint;
    const int end = l.panel_y + l.panel_height;
    const bool face = v.aiming && !v.placing && l.panel_width >= 40 && l.panel_height >= 3;
    const int face_w = 5, face_h = 3;
    const int right = l.panel_x + l.panel_width - (face ? face_w + 1 : 0);
    const int x = l.panel_x;
    // The players' column is as wide as their lines (a whole group of pocketed balls, long
    // names), from 36 columns up to what leaves the message 24 beside it.
    int widest = 0;
    for (int player = 1; player <= players(v); ++player) {
        Line line = name_line(f, player, right - x);
        line.push_back({"  " + player_detail(f, player).text, {}});
        widest = std::max(widest, width_of(line));
    }
    // Snooker's status line shares the column: room for it whole where there is some.
    if (snooker_panel(v))
        widest = std::max(widest, display_width(snooker_status(v)));
    const int pw = std::min(std::max(36, std::min(widest, right - x - 25)), right - x);
    const int mid_x = x + pw + 1, mid_w = right - mid_x - 1;
    const bool beside = mid_w >= 16;
    // The last row holds the legend and the hint; the rows above it the rest.
    const int rows = std::max(0, l.panel_height - 1);
    // The terminal leaves the screen's bottom-right cell alone (it would scroll): stop short.
    const int last_w = (l.panel_height > face_h || !face ? l.panel_width : right - x) - 1;
    draw_legend_row(f, x, end - 1, last_w);

    // The left column, in screen order with what goes first when rows run short (the larger
    // number first): title 4, players 0, balls of no group 3, message 1, call 2.
    struct Row {
        Line line;
        int drop;
    };
    std::vector<Row> left;
    left.push_back({header(v, true), 4});
    for (int player = 1; player <= players(v); ++player) {
        Line line = name_line(f, player, pw);
        const Piece detail = player_detail(f, player);
        if (!detail.text.empty()) {
            line.push_back({"  ", {}});
            line.push_back(detail);
        }
        left.push_back({line, 0});
    }
    if (snooker_panel(v))
        left.push_back({{{snooker_status(v, pw), mark}}, 0});
    const std::string loose = loose_balls(v);
    if (!loose.empty())
        left.push_back({{{loose, dim}}, 3});
    std::vector<Line> message = wrapped(v.message, beside ? mid_w : right - x, {});
    std::vector<Line> call = wrapped(call_text(v), beside ? mid_w : right - x, call_style(v));
    if (!beside) {
        for (Line& line : message)
            left.push_back({line, 1});
        for (Line& line : call)
            left.push_back({line, 2});
    }
    while (static_cast<int>(left.size()) > rows && !left.empty()) {
        // The balls of no group can share the title's row ("8-ball  pocketed 3 11"), or the
        // race's alone.
        if (left.size() > 3 && left.front().drop == 4 && left[3].drop == 3) {
            bool merged = false;
            for (const bool title : {true, false}) {
                Line line = header(v, title);
                if (!line.empty())
                    line.push_back({"  ", {}});
                line.push_back({loose, dim});
                if (width_of(line) <= pw) {
                    left.front() = {line, 3};
                    left.erase(left.begin() + 3);
                    merged = true;
                    break;
                }
            }
            if (merged)
                continue;
        }
        auto worst = left.begin();
        for (auto it = left.begin(); it != left.end(); ++it)
            if (it->drop >= worst->drop)
                worst = it;
        left.erase(worst);
    }
    // Message rows left out from the end: the last one kept says so.
    if (!beside && std::ranges::count(left, 1, &Row::drop) < static_cast<long>(message.size()))
        for (auto it = left.rbegin(); it != left.rend(); ++it)
            if (it->drop == 1) {
                mark_cut(it->line, right - x, f.paint.utf8());
                break;
            }
    // Snooker's frame score lost its row with the title: it goes under the message.
    if (beside && snooker_panel(v) && !frames_text(v).empty() &&
        (left.empty() || left.front().drop != 4))
        call = wrapped(frames_text(v), mid_w, bold);
    for (std::size_t i = 0; i < left.size(); ++i)
        draw_line(p, x, l.panel_y + static_cast<int>(i), left[i].line,
                  left[i].drop == 1 || left[i].drop == 2 ? right - x : pw);

    if (beside) {
        // The call is short and about the shot at hand: it keeps its rows, the message the rest;
        // at a hall table the newest chat keeps a row when there are three.
        const int chat_rows = !v.chat.empty() && rows >= 3 ? 1 : 0;
        const int call_rows = std::min(static_cast<int>(call.size()),
                                       std::max(0, rows - chat_rows - (message.empty() ? 0 : 1)));
        const int message_rows =
            std::min(static_cast<int>(message.size()), rows - call_rows - chat_rows);
        if (message_rows > 0 && message_rows < static_cast<int>(message.size()))
            mark_cut(message[static_cast<std::size_t>(message_rows - 1)], mid_w, f.paint.utf8());
        int y = l.panel_y;
        for (int i = 0; i < message_rows; ++i)
            draw_line(p, mid_x, y++, message[static_cast<std::size_t>(i)], mid_w);
        for (int i = 0; i < call_rows; ++i)
            draw_line(p, mid_x, y++, call[static_cast<std::size_t>(i)], mid_w);
        for (const Line& line : chat_tail(v, mid_w, l.panel_y + rows - y, f.paint.utf8()))
            draw_line(p, mid_x, y++, line, mid_w);
    }
    if (face)
        draw_spin_face(f, right + 1, l.panel_y, face_w, face_h);
}

} // namespace

void draw_panel(const Frame& f) {
    if (f.layout.panel_width <= 0 || f.layout.panel_height <= 0)
        return;
    if (f.layout.panel_below)
        draw_below_panel(f);
    else
        draw_side_panel(f);
}

} // namespace termpool::tui
