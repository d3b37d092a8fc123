#pragma once
/// \file
/// Snooker's balls and the marks of its table: which ball is which, what each is worth, the
/// baulk line, the D and the six colour spots. The marks are given for the 12 ft table and
/// scaled with the table's length, so a smaller table keeps the same layout in proportion.
///
/// The baulk end is x = 0 (as the head of a pool table); the top cushion is x = L. Looking up
/// the table from baulk (along +x), the yellow is on the right of the D (smaller y).

#include <termpool/ball.hpp>
#include <termpool/table.hpp>
#include <termpool/vec.hpp>
#include <vector>

namespace termpool {

/// Ball ids in snooker: 0 the cue ball, 1..15 the reds, then the colours in the order they are
/// taken at the end of a frame.
inline constexpr int snooker_first_red = 1;
inline constexpr int snooker_last_red = 15; ///< the last of the reds 1..15
inline constexpr int snooker_yellow = 16;   ///< worth 2
inline constexpr int snooker_green = 17;    ///< worth 3
inline constexpr int snooker_brown = 18;    ///< worth 4
inline constexpr int snooker_blue = 19;     ///< worth 5
inline constexpr int snooker_pink = 20;     ///< worth 6
inline constexpr int snooker_black = 21;    ///< worth 7
/// Number of balls in a snooker set, the cue ball included.
inline constexpr int snooker_ball_count = 22;

/// Radius of a snooker ball, m (52.5 mm across).
inline constexpr double snooker_ball_radius = 0.02625;
/// Mass of a snooker ball, kg (about 142 g; the cue ball the same).
inline constexpr double snooker_ball_mass = 0.142;

/// Playing area of a 12 ft snooker table between the cushion noses, m.
inline constexpr double snooker_table_length = 3.569;
/// Width of that playing area, m.
inline constexpr double snooker_table_width = 1.778;

/// True for a red (ids 1..15).
constexpr bool is_snooker_red(int id) {
    return id >= snooker_first_red && id <= snooker_last_red;
}

/// True for a colour (yellow to black).
constexpr bool is_snooker_colour(int id) {
    return id >= snooker_yellow && id <= snooker_black;
}

/// Points a ball is worth when potted: 1 for a red, 2 (yellow) to 7 (black) for a colour, 0
/// for the cue ball or an unknown id.
constexpr int snooker_value(int id) {
    return is_snooker_red(id) ? 1 : is_snooker_colour(id) ? id - snooker_yellow + 2 : 0;
}

/// Distance of the baulk line from the baulk cushion on a 12 ft table, m (29 in).
inline constexpr double snooker_baulk_distance = 0.737;
/// Radius of the D on a 12 ft table, m (11.5 in).
inline constexpr double snooker_d_radius = 0.292;
/// Distance of the black spot from the top cushion on a 12 ft table, m (12.75 in).
inline constexpr double snooker_black_distance = 0.324;

/// x of the baulk line on `table`.
double snooker_baulk_x(const Table& table);
/// Radius of the D on `table`, m.
double snooker_d_radius_on(const Table& table);
/// Centre of the D: the middle of the baulk line (the brown spot).
Vec2 snooker_d_centre(const Table& table);
/// True when `p` is in the D (on its line counts as in): on or behind the baulk line and within
/// the D's radius of its centre.
bool in_snooker_d(const Table& table, Vec2 p);
/// The spot of a colour (yellow to black); the centre of the table for any other id.
Vec2 snooker_spot(const Table& table, int colour);

/// Where colour `colour` is re-spotted among `balls` (of radius `R`; the colour itself is
/// ignored): on its own spot if that is free, else on the free spot of the highest value, else
/// as near its own spot as possible on the straight line towards the top cushion, else on that
/// line towards the baulk cushion. A spot is free when the ball there would touch no other.
Vec2 snooker_respot(const Table& table, const std::vector<Ball>& balls, int colour, double R);

} // namespace termpool
