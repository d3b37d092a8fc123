#pragma once
// The parts of a frame, each drawn by its own file into a shared Painter. render.cpp calls them
// in order: table, aim, balls, labels, close-up, status rows, panel, overlays.

#include <string>
#include <utility>
#include <vector>

#include "tui/painter.hpp"
#include "tui/view.hpp"

namespace termpool::tui {

/// What every drawing function needs: the view, the layout and the painter, plus the table's
/// frame (felt and rails) in cells.
struct Frame {
    const View& view;                                       ///< what to draw
    const Layout& layout;                                   ///< where
    Painter& paint;                                         ///< into what
    int felt_x = 0, felt_y = 0, felt_w = 0, felt_h = 0;     ///< the playing surface, cells
    int frame_x = 0, frame_y = 0, frame_w = 0, frame_h = 0; ///< surface and rails, cells

    /// A frame for a fitting layout.
    Frame(const View& v, const Layout& l, Painter& p);
    /// The table's width W (0 without a table).
    double table_width() const { return view.table ? view.table->width : 0; }
    /// The cell holding table point `p`; false when it is not a finite, sane position.
    bool cell_of(Vec2 p, int& x, int& y) const;
    /// True when (x, y) is on the playing surface.
    bool on_felt(int x, int y) const {
        return x >= felt_x && y >= felt_y && x < felt_x + felt_w && y < felt_y + felt_h;
    }
    /// True when (x, y) is on the playing surface or the rails.
    bool on_frame(int x, int y) const {
        return x >= frame_x && y >= frame_y && x < frame_x + frame_w && y < frame_y + frame_h;
    }
    /// The style of the felt.
    Style felt() const { return {Colour::normal, Colour::felt}; }
};

/// Felt, rails, cushions, pockets, head string and foot spot (on the snooker table its marks).
void draw_table(const Frame& f);
/// The snooker table's baulk line, D and six colour spots, faint on the felt (draw_table calls
/// it before the balls, which cover them).
void draw_snooker_marks(const Frame& f);
/// Pocket numbers while a pocket is being called (after the balls, so that they stay visible).
void draw_pocket_labels(const Frame& f);
/// The aim line and aiming aid, the cue and the pointer's marker.
void draw_aim(const Frame& f);
/// True when balls 10..15 get two-cell labels at this scale (see wide_labels).
bool labels_wide(const Frame& f);
/// The balls on the table, each on the cell of its centre; returns the cells they took.
std::vector<std::pair<int, int>> draw_balls(const Frame& f);
/// True when a ball on the table covers table point `point` (a spot under it is not drawn).
bool under_a_ball(const View& v, Vec2 point);
/// Where the close-up goes: cells [x, x + w) x [y, y + h), border included, in a corner of the
/// felt, as tall as it can be while it covers neither the contact nor the cue ball on the
/// table (the corner farthest from the contact first); w = 0 when the felt is too small.
struct CloseUpBox {
    int x = 0, y = 0, w = 0, h = 0; ///< the box, border included
};
/// The close-up's box for this frame (see CloseUpBox).
CloseUpBox close_up_box(const Frame& f);
/// The cut angle of a close-up's contact, degrees: between the cue ball's heading and the line
/// of centres (0 full ball, towards 90 ever thinner).
double close_up_cut_deg(const CloseUp& c);
/// The close-up of the contact (View::close_up), while aiming and when shown.
void draw_close_up(const Frame& f);
/// The power bar, speed, power mode, spin and elevation line and shoot button.
void draw_status(const Frame& f);
/// The game and the race, players with racks won, groups and their pocketed balls (9-ball:
/// fouls), other pocketed balls, the message, the called pocket in words, the spin diagram with
/// the cue's elevation, the legend and the help hint.
void draw_panel(const Frame& f);
/// A box with `text` ('\n' between lines), placed where it covers none of the `keep` cells
/// (the balls): centred if it can, else over the panel, else wherever it covers the fewest,
/// nearest the centre.
void draw_box(const Frame& f, const std::string& text,
              const std::vector<std::pair<int, int>>& keep);
/// The help overlay, page `page` of help_page_count (clamped), with how to turn and close it.
void draw_help(Painter& paint, int page);

/// "+0.2", "-0.25", "0.0": a tip offset with one or two decimals.
std::string format_offset(double value);
/// "elev 30°" ("elev 30deg" without UTF-8): the cue's elevation, to a tenth of a degree.
std::string format_elevation(double deg, bool utf8);
/// How the elevation is written: marked (as a warning is) while the strike as set cannot be
/// played, plain otherwise.
Style elevation_style(const View& v, const Painter& p);

} // namespace termpool::tui
