// The lobby's frame: a title row, the tables as rows of columns (the marked one reversed),
// who is in the hall, the message and the keys at the bottom, and a box over it all for the
// questions (a new table's settings, a seat that waits for this player).

#include "tui/lobby_view.hpp"

#include <algorithm>
#include <termpool/game_registry.hpp>
#include <termpool/race.hpp>

#include "tui/ball_style.hpp"
#include "tui/painter.hpp"
#include <termpool/text_width.hpp>

namespace termpool::tui {
namespace {

constexpr int min_width = 40, min_height = 10;
// The Size column holds the longest table name, "snooker", and a space.
constexpr int size_w = 8;
// The Race column holds the longest race, a snooker best of 197 ("bo197"), and a space.
constexpr int race_w = 6;
// The Assist column holds the longest assist, "standard", and a space.
constexpr int assist_w = 9;

const Style dim{Colour::dim};
const Style bold{Colour::normal, Colour::normal, true};

std::string seat_words(const hall::SeatView& seat) {
    switch (seat.kind) {
    case hall::SeatKind::empty:
        return "(empty)";
    case hall::SeatKind::away:
        return seat.name + " (away)";
    case hall::SeatKind::player:
    case hall::SeatKind::computer:
        return seat.name;
    }
    return "";
}

std::string padded(const std::string& text, int columns) {
    const std::string cut = truncate_to_width(text, columns);
    return cut +
           std::string(static_cast<std::size_t>(std::max(0, columns - display_width(cut))), ' ');
}

// One table's row; `seat_w` columns for each seat, the extras only where the row has room.
std::string table_row(const hall::TableView& t, int seat_w, bool extras) {
    std::string row = padded(std::to_string(t.number), 5) + padded(game_title(t.game), 18);
    if (extras)
        // A snooker match is best of N frames: "bo5" for a race to 3.
        row += padded(table_size_name(t.size), size_w) +
               padded(game_row(t.game).scoring == Scoring::points && t.race_to > 1
                          ? "bo" + std::to_string(best_of_for_race(t.race_to))
                          : std::to_string(t.race_to),
                      race_w) +
               padded(assist_name(t.assist), assist_w);
    row += padded(seat_words(t.seats[0]), seat_w) + " " + padded(seat_words(t.seats[1]), seat_w) +
           " " + padded(hall::table_state_name(t.state), 8);
    if (extras)
        row += " " + std::to_string(t.spectators);
    return row;
}

std::string header_row(int seat_w, bool extras) {
    std::string row = padded("#", 5) + padded("Game", 18);
    if (extras)
        row += padded("Size", size_w) + padded("Race", race_w) + padded("Assist", assist_w);
    row += padded("Seat 1", seat_w) + " " + padded("Seat 2", seat_w) + " " + padded("State", 8);
    if (extras)
        row += " Watching";
    return row;
}

std::string where_words(const hall::PlayerView& p) {
    if (p.table == 0)
        return p.name;
    return p.name + (p.seat == 0 ? " (watching " : " (table ") + std::to_string(p.table) + ")";
}

void draw_overlay_box(Painter& p, const std::string& text, int width, int height) {
    std::vector<std::string> lines;
    for (std::size_t start = 0; start <= text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string line = text.substr(start, end - start);
        // A line that fits keeps its spacing (the forms line their values up).
        if (display_width(line) <= width - 6)
            lines.push_back(line);
        else
            for (std::string& part : wrap_to_width(line, width - 6))
                lines.push_back(std::move(part));
        start = end + 1;
    }
    int inner = 0;
    for (const std::string& line : lines)
        inner = std::max(inner, display_width(line));
    const int w = std::min(width, inner + 4);
    const int h = std::min(height, static_cast<int>(lines.size()) + 2);
    const int x = (width - w) / 2, y = (height - h) / 2;
    const Style box{Colour::normal, Colour::normal, false, true};
    p.fill(x, y, w, h, box);
    for (int i = 0; i < h - 2 && i < static_cast<int>(lines.size()); ++i)
        p.text(x + 2, y + 1 + i, lines[static_cast<std::size_t>(i)], box, w - 4);
}

// The table list's place: its first row on screen, how many rows it has, and the index of
// the table on its first row (it scrolls to keep the marked one in view).
struct ListWindow {
    int top = 3;
    int rows = 1;
    int first = 0;
};

ListWindow list_window(const LobbyView& v, int height) {
    // Rows: title, blank, header, tables..., blank, people (2), blank, message (2), keys.
    constexpr int message_rows = 2, people_rows = 2;
    ListWindow w;
    w.rows = std::max(1, height - 1 - w.top - message_rows - people_rows - 2);
    const int count = static_cast<int>(v.tables.size());
    const int selected = std::clamp(v.selected, 0, std::max(0, count - 1));
    w.first = std::clamp(selected - w.rows / 2, 0, std::max(0, count - w.rows));
    return w;
}

} // namespace

int lobby_table_at(const LobbyView& v, int height, int y) {
    if (height < min_height)
        return -1;
    const ListWindow w = list_window(v, height);
    const int index = w.first + y - w.top;
    return y >= w.top && y < w.top + w.rows && index < static_cast<int>(v.tables.size()) ? index
                                                                                         : -1;
}

Grid render_lobby(const LobbyView& v, const Capabilities& caps, int width, int height) {
    Grid grid(width, height);
    Painter p(grid, caps);
    if (width < min_width || height < min_height) {
        const std::string text = "Please enlarge the terminal (need " + std::to_string(min_width) +
                                 "x" + std::to_string(min_height) + ")";
        p.text(std::max(0, (width - display_width(text)) / 2), height / 2, text, {}, width);
        return grid;
    }
    const std::string title =
        "termpool hall" + (v.name.empty() ? "" : (caps.utf8 ? " \u2014 " : " - ") + v.name);
    p.text(1, 0, title, bold, width - 2);
    const std::string people = std::to_string(v.players.size()) +
                               (v.players.size() == 1 ? " person here" : " people here");
    if (v.connected && display_width(title) + display_width(people) + 4 <= width)
        p.text(width - 1 - display_width(people), 0, people, dim);

    const bool extras = width >= 90;
    const int fixed = 5 + 18 + 2 + 8 + (extras ? size_w + race_w + assist_w + 9 : 0);
    const int seat_w = std::max(8, std::min(24, (width - 2 - fixed) / 2));
    const ListWindow window = list_window(v, height);
    const int list_top = window.top, list_rows = window.rows, keys_row = height - 1;
    const int message_rows = 2, people_rows = 2;
    p.text(1, 2, header_row(seat_w, extras), dim, width - 2);
    if (v.tables.empty()) {
        // Before the hall has answered there is nothing to tell of its tables.
        p.text(1, list_top,
               v.connected ? "No tables yet: c creates one." : "Not in the hall yet: no tables.",
               {}, width - 2);
    } else {
        const int count = static_cast<int>(v.tables.size());
        const int selected = std::clamp(v.selected, 0, count - 1);
        const int first = window.first;
        for (int i = first; i < count && i - first < list_rows; ++i) {
            const bool marked = i == selected;
            const Style style{Colour::normal, Colour::normal, marked, marked};
            const std::string row =
                table_row(v.tables[static_cast<std::size_t>(i)], seat_w, extras);
            p.fill(1, list_top + i - first, width - 2, 1, marked ? style : Style{});
            p.text(1, list_top + i - first, row, style, width - 2);
        }
        if (count > list_rows)
            p.text(width - 8, list_top + list_rows - 1, "(" + std::to_string(count) + ")", dim);
    }

    int y = list_top + list_rows + 1;
    std::string here;
    for (const hall::PlayerView& player : v.players)
        here += (here.empty() ? "In the hall: " : ", ") + where_words(player);
    const auto people_lines = wrap_to_width(here, width - 2);
    for (int i = 0; i < people_rows && i < static_cast<int>(people_lines.size()); ++i)
        p.text(1, y + i, people_lines[static_cast<std::size_t>(i)], dim, width - 2);
    y += people_rows + 1;
    const auto message_lines = wrap_to_width(v.message, width - 2);
    for (int i = 0; i < message_rows && i < static_cast<int>(message_lines.size()); ++i)
        p.text(1, y + i, message_lines[static_cast<std::size_t>(i)],
               v.connected ? Style{} : Style{Colour::highlight, Colour::normal, true}, width - 2);

    const std::string keys = width >= 76
                                 ? "c create  Enter sit  1/2 that seat  w watch  Up/Down choose  "
                                   "q quit"
                                 : "c new  Enter sit  w watch  q quit";
    p.text(1, keys_row, keys, dim, width - 2);
    if (!v.overlay.empty())
        draw_overlay_box(p, v.overlay, width, height);
    return grid;
}

} // namespace termpool::tui
