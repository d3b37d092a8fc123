#pragma once
// Pure input math for the game loop: aim angles, power, spin steps and the aiming aid's
// geometry. Nothing here draws or reads input; it is all plain functions of numbers.

#include <termpool/assist.hpp>
#include <termpool/ball.hpp>
#include <termpool/table.hpp>
#include <vector>

namespace termpool::tui {

/// Slowest cue-ball speed the power bar gives, m/s.
inline constexpr double min_shot_speed = 0.3;
/// Fastest cue-ball speed of a break shot, m/s.
inline constexpr double max_break_speed = 12.0;
/// Fastest cue-ball speed of any other shot, m/s.
inline constexpr double max_shot_speed = 7.0;
/// Largest tip offset either way, as a fraction of R (the simulator's limit).
inline constexpr double max_spin = 0.5;
/// Pointer distance from the cue ball that gives full power in distance mode, m.
inline constexpr double full_power_distance = 1.0;

/// Aim angle in degrees counter-clockwise from +x, in [0, 360), from the cue ball towards the
/// pointer. 0 when the pointer is on the cue ball's centre (callers keep their aim then).
double aim_from_pointer(Vec2 cue, Vec2 pointer);

/// `deg` turned by `delta` degrees, wrapped to [0, 360). Rounded to a millionth of a degree so
/// that many 0.1-degree steps add up to round numbers.
double turn(double deg, double delta);

/// Distance mode: 0 at the cue ball, growing linearly to 1 at `full_power_distance` and beyond.
double power_from_distance(double metres);

/// Timed mode: a triangle wave over `period` seconds, 0 at the start, 1 halfway, 0 at the end.
double power_from_time(double seconds, double period = 1.5);

/// Cue-ball speed for a power in [0, 1]: from `min_shot_speed` up to `max_break_speed` on the
/// break, `max_shot_speed` otherwise (power is clamped first).
double speed_from_power(double power, bool is_break);

/// The power that gives `speed` (the inverse of speed_from_power, clamped to [0, 1]): the bar
/// of a shot someone else aims, or the computer.
double power_from_speed(double speed, bool is_break);

/// A tip offset clamped to +-`max_spin`, rounded to a millionth so that steps stay tidy.
double clamp_spin(double offset);

/// What the aiming aid shows for one aim: polylines in table coordinates, for View::cue_path,
/// View::object_path and View::deflect_path.
struct AimPreview {
    std::vector<Vec2> cue_path;     ///< the cue ball's centre from its spot to its first contact
                                    ///< (through a cushion to the next when asked: a kick)
    int object_ball = -1;           ///< id of the first ball met, -1 when none is
    int cushion = -1;               ///< index into Table::cushions of the first cushion met
                                    ///< (before the ball, in a kick), else -1
    std::vector<Vec2> kick_leg;     ///< a path through a rail: its part up to the rail
    bool has_ghost = false;         ///< a ball is met: `ghost` is where the cue ball touches it
    Vec2 ghost;                     ///< the cue ball's centre at contact
    std::vector<Vec2> object_path;  ///< the object ball's start along the line of centres
    std::vector<Vec2> deflect_path; ///< the cue ball's tangent line after contact (empty when
                                    ///< the hit is full, as the cue ball then stops or rolls on)
};

/// Fills the aid's lines after the cue ball's centre, moving along the unit vector `d`,
/// reaches `contact` touching ball `object_id`: the object ball and the ghost ball, the object
/// ball's path along the line of centres and the cue ball's along the tangent line on the side
/// away from the object ball (none for a full hit), each up to its own first contact and at
/// most `aid_length` metres; with `rebounds`, a line that meets a cushion goes on off it (mirror
/// reflection) that many times, each leg again at most `aid_length`.
void add_contact_lines(AimPreview& out, const Table& table, const std::vector<Ball>& balls,
                       double R, Vec2 contact, Vec2 d, int object_id, double aid_length,
                       int rebounds = 0);

/// Casts the cue ball from `cue` at `aim_deg` against the balls on the table (circles of radius
/// 2R around their centres; the cue ball, id 0, and pocketed balls are ignored) and against the
/// cushions and jaws moved R towards the table (and the jaw points as circles of radius R).
/// After a ball contact the object ball's path runs along the line of centres, the cue ball's
/// along the tangent line on the side away from the object ball, each up to its own first
/// contact and at most `aid_length` metres.
AimPreview preview_shot(const Table& table, const std::vector<Ball>& balls, double R, Vec2 cue,
                        double aim_deg, double aid_length = 0.6);

/// How the cue ball reaches a target.
enum class TargetLine {
    straight, ///< straight: the cue ball meets it before any other ball
    kick,     ///< hidden: off one rail (mirror aim; a turn's opening settles it: refine_kick)
    none,     ///< hidden from every line tried: aimed at its centre all the same
    /// hidden: off one rail at the mirror aim, which the simulator found no aim near to make
    /// meet the ball first (refine_kick): the kick may well foul
    uncertain_kick,
};

/// A target ball with its easiest pocket.
struct TargetChoice {
    int ball = 0;          ///< the object ball
    int pocket = 0;        ///< its easiest pocket 1..6, 0 when none looks makeable
    double aim_deg = 0;    ///< the aim that sends the ball there (straight at it if none)
    double difficulty = 0; ///< smaller is easier: cut angle in degrees plus distance terms
    TargetLine line = TargetLine::straight; ///< how the aim reaches it
};

/// The legal targets (ids in `legal`, which are on the table) ranked easiest first: for each,
/// the pocket with the smallest cut angle and distance (cue ball to ghost ball, ball to pocket).
/// Straight lines only. Every aim offered meets its target before any other ball; a pocket
/// whose line is blocked is passed over (the cue ball's line) or ranked harder (the object
/// ball's). A hidden target is offered as a one-rail kick (mirror aim) after the visible ones,
/// and one with no line at all comes last, aimed at its centre.
std::vector<TargetChoice> rank_targets(const Table& table, const std::vector<Ball>& balls, double R,
                                       Vec2 cue, const std::vector<int>& legal);

/// The aims a turn opens with under `assist`, in `rank_targets`' order (the '[' and ']' keys
/// go through them). Guided: rank_targets' own, at the ghost ball of each ball's easiest pot.
/// Standard and pro: at the centre of the same balls, a full hit that pots nothing by itself
/// unless the pot is straight (across the silhouette when another ball hides the centre, the
/// kick's and the hidden ball's aims as ranked).
std::vector<TargetChoice> rank_openings(const Table& table, const std::vector<Ball>& balls,
                                        double R, Vec2 cue, const std::vector<int>& legal,
                                        Assist assist);

/// The ids of `rank_targets`, easiest first (for the '[' and ']' keys).
std::vector<int> targets_easiest_first(const Table& table, const std::vector<Ball>& balls, double R,
                                       Vec2 cue, const std::vector<int>& legal);

} // namespace termpool::tui
