#pragma once
// What the terminal game shows, as plain data: the screen is a grid of cells that a renderer
// fills from a View, and only terminal.cpp copies it to curses. Nothing here knows curses, so
// frames can be built and compared in tests without a terminal.

#include <algorithm>
#include <cstdint>
#include <string>
#include <termpool/ball.hpp>
#include <termpool/game_registry.hpp>
#include <termpool/rules.hpp>
#include <termpool/table.hpp>
#include <vector>

namespace termpool::tui {

/// Colour roles; the terminal maps them to 256 colours, 8 colours or nothing.
enum class Colour : std::uint8_t {
    normal,   ///< the terminal's default
    felt,     ///< the cloth
    rail,     ///< the wooden rail around the cushions
    cushion,  ///< the rubber nose
    pocket,   ///< a pocket hole
    white,    ///< the cue ball, stripes' background, light text
    black,    ///< the 8, dark text
    ink,      ///< a ball's dark digits: the terminal's own black (the shortest escape)
    yellow,   ///< 1 and 9
    blue,     ///< 2 and 10
    red,      ///< 3 and 11, the power bar
    purple,   ///< 4 and 12
    orange,   ///< 5 and 13
    green,    ///< 6 and 14
    maroon,   ///< 7 and 15
    brown,    ///< snooker's brown
    pink,     ///< snooker's pink
    aim,      ///< the aim line and the cue
    ghost,    ///< the ghost ball and the predicted paths
    dim,      ///< secondary text
    highlight ///< the player to shoot, the selected pocket
};

/// How a cell is drawn.
struct Style {
    Colour fg = Colour::normal; ///< foreground role
    Colour bg = Colour::normal; ///< background role
    bool bold = false;          ///< bold (also used to mark stripes in monochrome)
    bool reverse = false;       ///< reverse video (solids in monochrome)
    /// Exact equality.
    bool operator==(const Style&) const = default;
};

/// One character cell: a UTF-8 glyph of display width 1 and its style. A wide character (CJK,
/// emoji: two columns) sits in its left cell and leaves the right cell's glyph empty; a terminal
/// writes nothing for an empty glyph. Combining marks are appended to the glyph they follow.
struct Cell {
    std::string glyph = " "; ///< one column wide, or empty for the right half of a wide one
    Style style;             ///< colours and attributes
    /// Exact equality.
    bool operator==(const Cell&) const = default;
};

/// A screenful of cells, row-major.
struct Grid {
    int width = 0;           ///< columns
    int height = 0;          ///< rows
    std::vector<Cell> cells; ///< width * height cells

    /// A blank grid; negative sizes count as 0.
    Grid(int w, int h)
        : width(std::max(w, 0)), height(std::max(h, 0)),
          cells(static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {}
    /// The cell at column x, row y (must be inside).
    Cell& at(int x, int y) { return cells[static_cast<std::size_t>(y * width + x)]; }
    /// The cell at column x, row y (must be inside).
    const Cell& at(int x, int y) const { return cells[static_cast<std::size_t>(y * width + x)]; }
    /// True when (x, y) is inside.
    bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
};

/// What the terminal can show.
struct Capabilities {
    int colours = 256; ///< 256, 8 or 0 (monochrome)
    bool utf8 = true;  ///< half blocks, Braille and box drawing; else plain ASCII
    bool mouse = true; ///< mouse reports are decoded (terminfo has kmous)
};

/// Where things go on the screen for one terminal size, and the mapping between table
/// coordinates (metres) and cells. Cells are taken to be twice as tall as wide.
struct Layout {
    bool fits = false;          ///< false when the terminal is smaller than the minimum
    int min_width = 40;         ///< the minimum size, for the "please enlarge" message
    int min_height = 14;        ///< the minimum size
    double cells_per_metre = 0; ///< columns per metre
    double rows_per_metre = 0;  ///< rows per metre: about half of cells_per_metre (make_layout)
    double table_left = 0;      ///< column of x = 0 (the cushion nose), fractional
    double table_top = 0;       ///< row of y = W (the top cushion nose), fractional
    int panel_x = 0, panel_y = 0, panel_width = 0, panel_height = 0; ///< the text panel
    bool panel_below = false; ///< panel under the table (narrow terminals) or to its right
    int status_y = 0;         ///< row of the power bar; the spin line is the row below
    int felt_cols = 0;        ///< columns of the playing surface (from table_left)
    int felt_rows = 0;        ///< rows of the playing surface (from table_top)
    int status_x = 0;         ///< first column of the status rows
    int status_width = 0;     ///< columns of the status rows
    int button_x = 0, button_y = 0, button_width = 0; ///< the "[ shoot ]" button (one row)
};

/// Columns of the rail (cushion and wood) left and right of the playing surface; above and
/// below it is one row, which is as tall as two columns are wide.
inline constexpr int rail_cols = 2;
/// Rows of the rail above and below the playing surface.
inline constexpr int rail_rows = 1;

/// True when cell (x, y) is on the shoot button (drawn while aiming).
inline bool on_shoot_button(const Layout& l, int x, int y) {
    return l.fits && y == l.button_y && x >= l.button_x && x < l.button_x + l.button_width;
}

/// Chooses the largest table that fits a terminal of `width` x `height` cells, leaving room for
/// the panel (to the right, or below when the terminal is narrow) and the status rows. The felt
/// has an odd number of rows and 4 k + 2 columns, so that the long axis and the foot and head
/// spots lie in the middle of cells: a rack drawn at its balls' own cells is then symmetric.
Layout make_layout(const Table& table, int width, int height);

/// Column and row (fractional) of the table point p; y grows upward on the table and downward
/// on the screen.
inline void to_cell(const Layout& l, double table_width, Vec2 p, double& col, double& row) {
    col = l.table_left + p.x * l.cells_per_metre;
    row = l.table_top + (table_width - p.y) * l.rows_per_metre;
}

/// The table point under the centre of cell (col, row).
inline Vec2 from_cell(const Layout& l, double table_width, double col, double row) {
    return {(col + 0.5 - l.table_left) / l.cells_per_metre,
            table_width - (row + 0.5 - l.table_top) / l.rows_per_metre};
}

/// The close-up of the contact the aid predicts (z): the cue ball and the ball it meets about
/// ten times larger, for judging a thin cut. Filled while aiming from the aid's prediction.
struct CloseUp {
    bool shown = false; ///< z turned it on
    int ball = -1;      ///< the object ball met first, -1 when none is (a cushion first)
    Vec2 cue;           ///< the cue ball's centre at contact (the ghost ball)
    Vec2 object;        ///< the object ball's centre
    Vec2 heading{1, 0}; ///< the cue ball's direction as it arrives (unit)
    Vec2 departure;     ///< the object ball's predicted direction (unit; zero when unknown)
};

/// Everything the renderer needs for one frame. The front end fills it; the renderer draws it.
struct View {
    const Table* table = nullptr;                    ///< the table geometry
    std::vector<Ball> balls;                         ///< balls to draw (pocketed ones are skipped)
    double ball_radius = 0.028575;                   ///< R
    GameType game = default_game;                    ///< for the panel
    std::string names[2] = {"Player 1", "Player 2"}; ///< the players
    int shooter = 1;                                 ///< whose turn it is (marker in the panel)
    Group groups[2] = {Group::open, Group::open};    ///< each player's group
    std::string message;                             ///< the message line (verdicts, prompts)
    bool aiming = false;                             ///< draw the cue, aim line and power bar
    double aim_deg = 0;             ///< cue direction, degrees counter-clockwise from +x
    double power = 0;               ///< 0..1 of the power bar
    double speed = 0;               ///< the cue-ball speed that power gives, m/s
    bool is_break = false;          ///< a break: full power is max_break_speed, not max_shot_speed
    bool time_power = false;        ///< power mode: false = distance, true = oscillating bar
    double side = 0, follow = 0;    ///< tip offsets, fractions of R (-0.5..0.5)
    double elevation_deg = 0;       ///< the cue's elevation above the cloth, degrees (0..80)
    bool strike_refused = false;    ///< the strike as set would jump: Space will not shoot it
    bool show_aid = true;           ///< draw the aiming aid below
    std::vector<Vec2> cue_path;     ///< predicted path of the cue ball up to its first contact
    bool has_ghost = false;         ///< draw a ghost ball
    Vec2 ghost;                     ///< where the cue ball touches the first object ball
    std::vector<Vec2> object_path;  ///< predicted direction of the object ball after contact
    std::vector<Vec2> deflect_path; ///< predicted direction of the cue ball after contact
    CloseUp close_up;               ///< the inset of the contact, when shown
    bool show_marker = false;       ///< draw the mouse aim marker
    Vec2 marker;                    ///< aim marker position on the table
    int called_pocket = 0;          ///< 1..6: highlight that pocket
    int called_ball = 0;            ///< the ball called into called_pocket (0: none named)
    int call_off_ball = 0;          ///< a combination: the ball hit first, off which called_ball
    bool called_safety = false;     ///< a safety is called
    int foul_ball = 0;              ///< the aim meets first a ball it may not: the panel warns
    std::vector<int> dimmed_balls;  ///< drawn dim: balls the shooter may not hit first
    bool placing = false;           ///< ball in hand: the cue ball follows the pointer
    bool placement_legal = true;    ///< whether the current spot is allowed
    bool help = false;              ///< show the help overlay
    int help_page = 0;              ///< its page, 0-based (see help_page_count)
    int race_to = 0;                ///< racks needed to win the match; 0: a single game
    int racks_won[2] = {0, 0};      ///< racks each player has won in the match
    int fouls[2] = {0, 0};          ///< consecutive fouls of each player (9-, 10-ball)
    bool practice = false;          ///< practice: one player, no groups or fouls in the panel
    // Snooker's score sheet for the panel (game == snooker, not practice).
    int scores[2] = {0, 0};         ///< snooker: each player's points in the frame
    int current_break = 0;          ///< snooker: the points of the visit at the table so far
    int highest_break[2] = {0, 0};  ///< snooker: each player's highest break of the frame
    BallOn ball_on = BallOn::red;   ///< snooker: what the player at the table is on
    bool free_ball = false;         ///< snooker: a free ball, any ball may be nominated
    int nominated = 0;              ///< snooker: the colour (or free ball) nominated, 0: none
    bool nomination_chosen = false; ///< snooker: the player picked it (else the aim's ball)
    int lowest_colour = 0;          ///< snooker: the colour on once the reds are gone
    int points_remaining = 0;       ///< snooker: the points still on the table
    int best_of = 0;                ///< snooker: frames of the match (best of N), 0: one frame
    std::string overlay; ///< a box of text (questions, game over), if any, clear of the balls
    std::vector<std::string> chat; ///< a hall table's chat, oldest first: the last lines show
    bool hall = false;             ///< a hall table: q leaves it, Tab opens the chat
};

/// Draws `view` into a grid of `width` x `height` with the given capabilities. When the layout
/// does not fit, the grid holds only "Please enlarge the terminal (need 40x14)" (blank when
/// even that does not fit). Never writes outside the grid, at any size.
Grid render(const View& view, const Layout& layout, const Capabilities& caps, int width,
            int height);

} // namespace termpool::tui
