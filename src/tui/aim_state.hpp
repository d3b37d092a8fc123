#pragma once
// The cue as the player at the table sets it: direction, power, spin, elevation, the call and
// the aiming aid's paths. Plain data with the few rules that belong to it; the App feeds it input.

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <termpool/rules.hpp>
#include <termpool/simulator.hpp>
#include <vector>

#include "tui/aim.hpp"
#include "tui/view.hpp"

namespace termpool::tui {

/// How far one press of e or E raises or lowers the cue, degrees.
inline constexpr double elevation_step_deg = 5.0;

/// The aim, the power bar, the spin and the call of the shot being set up.
struct AimState {
    using Clock = std::chrono::steady_clock;

    double aim_deg = 0;             ///< the cue's direction, degrees counter-clockwise from +x
    double power = 0.3;             ///< the power bar, 0 to 1
    double power_before_break = -1; ///< the power to return to after a break, -1: none held
    bool time_power = false;        ///< the bar swings and Space stops it
    Clock::time_point power_start;  ///< when the swinging bar started
    double side = 0, follow = 0;    ///< tip offsets, fractions of R
    double elevation_deg = 0;       ///< the cue's elevation above the cloth, degrees
    bool show_aid = true;           ///< draw the aiming aid
    bool close_up = false;          ///< draw the close-up of the contact (z)
    bool show_marker = false;       ///< draw the pointer's mark
    Vec2 marker;                    ///< where the pointer aimed
    bool dragging = false;          ///< a button is held: its distance sets the power
    bool drag_moved = false;        ///< the pointer moved while held: release shoots
    int called_pocket = 0;          ///< the pocket the shot calls, 0: none
    bool pocket_chosen = false;     ///< the player picked the pocket: keep it while aiming
    bool safety = false;            ///< a safety is called
    bool push_out = false;          ///< 9-ball, 10-ball: the shot is a push-out
    int nominated = 0;              ///< snooker: the colour (or free ball) nominated, 0: none
    bool nomination_chosen = false; ///< snooker: the player named it (else the aimed ball)
    int target_index = -1;          ///< which of the ranked targets the aim proposes
    TargetLine target_line = TargetLine::straight; ///< how the proposed aim reaches its ball
    int kick_ball = -1;               ///< a kick just proposed, to settle (refine_kick), -1: none
    double kick_mirror_deg = 0;       ///< that kick's mirror aim, as aim_at_target set it
    int preview_ball = -1;            ///< the ball the cue ball meets first (off one rail at most)
    Assist assist = Assist::standard; ///< how much of the aid shows, and where a turn opens
    AimPreview full_preview;          ///< the whole aid, off a rail: what the call reads
    AimPreview preview;               ///< the aid's paths as `assist` shows them
    /// The call of a shot someone else set up (the computer's, another terminal's being shown):
    /// shown and made as it is.
    std::optional<ShotCall> given_call;

    /// A new turn: no call, no spin, a level cue, no pointer mark, the easiest target first.
    void new_turn();
    /// A break has its own power: the bar starts at `break_power` for it (full for a pool
    /// break, a snooker break-off's soft one), and the player's own setting comes back for the
    /// shots after.
    void set_break(bool is_break, double break_power = 1.0);
    /// The power now (the swinging bar's position in timed mode).
    double current_power(Clock::time_point now) const;
    /// Applies a spin key (w/s/d/a and W/S/D/A finely, c centres); false for another text.
    bool spin_key(const std::string& text);
    /// Applies an elevation key (e raises the cue, E lowers it, by `elevation_step_deg` within
    /// 0..max_cue_elevation_deg; v levels it); false for another text.
    bool elevation_key(const std::string& text);
    /// The strike the cue as set gives at `now` (the swinging bar's position in timed mode).
    Strike strike(bool is_break, Clock::time_point now) const;
    /// The strike the cue as set gives at the bar's set power.
    Strike set_strike(bool is_break) const;
    /// Turns the cue to the proposed target `target_index` of `order` (kept in range). A kick
    /// is aimed at the ball's mirror image and settled by the next update_preview.
    void aim_at_target(const std::vector<TargetChoice>& order);
    /// Recomputes the aid from the simulator for the strike as set (at the bar's set power: in
    /// timed mode the last one it stopped at), the whole of it and as `assist` shows it, and
    /// proposes the pocket the object ball heads for most directly when `calls_pocket` says the
    /// shot at it names one. The ball met is the first one the cue ball reaches, straight or
    /// off one rail, so that a kick calls its ball too. A kick aim_at_target just proposed (the
    /// aim not turned since) is first settled with the simulator (refine_kick) at the power,
    /// spin and elevation set now, the turn's opening ones: one that meets its ball first off
    /// the rail, or, when none near the mirror aim does, the mirror aim as an uncertain kick.
    /// The player may change the power after; the aim is not settled again.
    void update_preview(const Table& table, const PhysicsParams& params,
                        const std::vector<Ball>& balls, bool is_break,
                        const std::function<bool(int ball)>& calls_pocket);
    /// The close-up of the contact the aid predicts, for View::close_up (not shown unless
    /// `close_up` is on; no ball when the cue ball meets a cushion first).
    CloseUp close_up_view(const std::vector<Ball>& balls) const;
};

} // namespace termpool::tui
