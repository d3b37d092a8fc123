#pragma once
/// \file
/// Table geometry: playing surface, cushions, pocket jaws and capture lines.
///
/// Origin at the corner of the cushion noses where x = 0 and y = 0, x along the long side.
/// Pockets are numbered counter-clockwise from the origin: 1 (0,0), 2 (L/2,0), 3 (L,0),
/// 4 (L,W), 5 (L/2,W), 6 (0,W).

#include <array>
#include <optional>
#include <string_view>
#include <termpool/enum_names.hpp>
#include <termpool/vec.hpp>

namespace termpool {

/// The three common pool table sizes and the snooker table (playing surface between the
/// cushion noses).
enum class TableSize {
    seven_foot, ///< 1.98 x 0.99 m
    eight_foot, ///< 2.34 x 1.17 m
    nine_foot,  ///< 2.54 x 1.27 m (default)
    snooker,    ///< 12 ft snooker table, 3.569 x 1.778 m, with snooker's smaller pockets
};

/// Every table size, pool's first, in the order menus offer them.
inline constexpr TableSize all_table_sizes[] = {TableSize::seven_foot, TableSize::eight_foot,
                                                TableSize::nine_foot, TableSize::snooker};

/// The table sizes' names, as the command line, a record and a scenario give them.
inline constexpr NameRow<TableSize> table_size_names[] = {
    {TableSize::seven_foot, "7ft"},
    {TableSize::eight_foot, "8ft"},
    {TableSize::nine_foot, "9ft"},
    {TableSize::snooker, "snooker"},
};
static_assert(names_in_order(table_size_names));

/// A straight piece of cushion rubber. Balls approach it from the side `normal` points to.
struct CushionSegment {
    Vec2 start;  ///< one end
    Vec2 end;    ///< the other end
    Vec2 normal; ///< unit normal pointing towards the playing area
    int pocket;  ///< 0 for a rail, else the pocket (1..6) whose jaw this is
    bool operator==(const CushionSegment&) const = default; ///< exact equality
};

/// One pocket: its mouth, jaws and the line behind which a ball centre is captured.
struct Pocket {
    int number = 0;      ///< 1..6
    Vec2 position;       ///< nominal position (the table corner or the middle of a long side)
    Vec2 capture_point;  ///< a point on the capture line
    Vec2 capture_normal; ///< unit normal of the capture line, pointing towards the table
    Vec2 region_min;     ///< box holding the jaws and the mouth, for quick rejection
    Vec2 region_max;     ///< upper corner of that box
    bool operator==(const Pocket&) const = default; ///< exact equality
};

/// A table: the playing surface and everything a ball can hit or fall into.
struct Table {
    TableSize size = TableSize::nine_foot; ///< nominal size
    double length = 2.54;                  ///< L, along x
    double width = 1.27;                   ///< W, along y
    /// The six rails (index 0..5) followed by the twelve jaws (two per pocket).
    std::array<CushionSegment, 18> cushions{};
    /// The twelve points where a rail turns into a jaw, with the pocket each belongs to.
    std::array<Vec2, 12> jaw_points{};
    /// Pocket number (1..6) of each jaw point.
    std::array<int, 12> jaw_point_pocket{};
    /// The six pockets, index 0 is pocket 1.
    std::array<Pocket, 6> pockets{};

    /// The foot spot (3L/4, W/2), where the apex ball of a rack sits.
    Vec2 foot_spot() const { return {0.75 * length, 0.5 * width}; }
    /// The head spot (L/4, W/2), where a rack places the cue ball.
    Vec2 head_spot() const { return {0.25 * length, 0.5 * width}; }
    /// x of the head string; the kitchen is x <= this.
    double head_string_x() const { return 0.25 * length; }
    /// Exact equality (the same table to the bit, NaN excepted).
    bool operator==(const Table&) const = default;
};

/// Geometry of the pocket mouths (WPA): widths between the points of the jaws, the angle between
/// rail and jaw measured through the rubber, and the depth behind the mouth line at which a
/// ball's centre is over the hole.
struct PocketSpec {
    double corner_mouth = 0.114;        ///< m
    double side_mouth = 0.127;          ///< m
    double corner_jaw_angle_deg = 142;  ///< degrees
    double side_jaw_angle_deg = 104;    ///< degrees
    double corner_capture_depth = 0.03; ///< m behind the mouth line
    double side_capture_depth = 0.02;   ///< m behind the mouth line
};

/// The pockets of a table size: the WPA's (the defaults of PocketSpec) on a pool table;
/// snooker's smaller, rounded ones (corner 86 mm, middle 105 mm at the cushion line) on the
/// snooker table.
PocketSpec pocket_spec(TableSize size);

/// Builds the table of the given size, with its own pockets (`pocket_spec`), for balls of
/// radius `ball_radius`.
Table make_table(TableSize size, double ball_radius = 0.028575);

/// Builds the table of the given size with the pockets of `spec`, for balls of radius
/// `ball_radius`.
Table make_table(TableSize size, double ball_radius, const PocketSpec& spec);

/// A table whose playing surface is `length` by `width` m (along x and y), with the pockets of
/// `spec`, for balls of radius `ball_radius`: for experiments on tables of other sizes (`termpool
/// bench --balls` scales the 9 ft table to hold more balls). Its nominal size is `size`.
Table make_table(double length, double width, double ball_radius, const PocketSpec& spec,
                 TableSize size = TableSize::nine_foot);

/// Name of a table size as used on the command line ("9ft", "snooker").
const char* table_size_name(TableSize size);

/// Parses "7ft", "8ft", "9ft" or "snooker"; nothing for anything else.
std::optional<TableSize> parse_table_size(std::string_view name);

/// How far a ball of radius `radius` centred at `p` presses into the cushion rubber, m: the
/// largest overlap with the face of any rail or jaw, their ends included; zero or less when it
/// touches none. A centre gone right through a face is refused by on_playing_surface's other
/// rules (the rectangle, the mouths), not by this.
double rubber_depth(const Table& table, Vec2 p, double radius);

/// Rubber depth, m, up to which a ball still counts as touching a cushion rather than in it:
/// round-off in a position of a few metres.
inline constexpr double rubber_tolerance = 1e-9;

/// True when a ball of radius `radius` centred at `p` is on the table: in no rubber (depth at
/// most `rubber_tolerance` against every rail and jaw), its centre strictly in front of every
/// pocket's capture line, and inside the rectangle of the cushion noses or in a pocket's mouth
/// between its jaws. The one rule of the world, the scenario parser, ball in hand and the game,
/// so that wherever the simulator leaves a ball may be given back to it.
bool on_playing_surface(const Table& table, Vec2 p, double radius);

/// Where a cursor at `from` moved by `step` puts a ball of radius `radius`: `from + step` if
/// the ball is on the table there; else that point drawn back into the band where the ball
/// clears every rail (so the cursor slides along a cushion), if it is on the table there;
/// else `from`.
Vec2 step_on_table(const Table& table, Vec2 from, Vec2 step, double radius);

} // namespace termpool
