// BreakScene: the break's views, built as App::compose builds them for an aiming player and
// for a shot that rolls.

#include "tui/break_scene.hpp"

#include <algorithm>
#include <cmath>
#include <termpool/rack.hpp>

#include "tui/aim.hpp"

namespace termpool::tui {

BreakScene::BreakScene(std::uint64_t seed)
    : table_(make_table(TableSize::nine_foot)),
      rack_(make_rack(table_, params_, RackType::eight_ball, game_rack_seed(seed, 0))),
      trajectory_(params_, rack_.size()) {
    // As App::start_aiming sets a break up at the default assist (standard): full power, full on
    // the easiest target, the aid.
    std::vector<int> targets;
    Vec2 cue;
    for (const Ball& b : rack_) {
        if (b.id == 0)
            cue = b.position;
        else
            targets.push_back(b.id);
    }
    aim_.new_turn();
    aim_.set_break(true);
    aim_.assist = Assist::standard;
    aim_.aim_at_target(
        rank_openings(table_, rack_, params_.ball_radius, cue, targets, Assist::standard));
    aim_.update_preview(table_, params_, rack_, true, [](int) { return false; });
    const ShotResult result =
        simulate_shot(table_, params_, rack_, aim_.set_strike(true), &trajectory_);
    animation_frames_ = static_cast<int>(std::ceil(result.rest_time * animation_fps));
}

View BreakScene::view(int index) const {
    index = std::clamp(index, 0, animation_frames_);
    View v;
    v.table = &table_;
    v.ball_radius = params_.ball_radius;
    v.shooter = 1;
    if (index == 0) {
        v.balls = rack_;
        v.message = "Player 1: aim (mouse, Left/Right), Space shoots";
        v.aiming = true;
        v.aim_deg = aim_.aim_deg;
        v.power = aim_.power;
        v.speed = speed_from_power(aim_.power, true);
        v.cue_path = aim_.preview.cue_path;
        v.has_ghost = aim_.preview.has_ghost;
        v.ghost = aim_.preview.ghost;
        v.object_path = aim_.preview.object_path;
        v.deflect_path = aim_.preview.deflect_path;
    } else {
        v.balls = trajectory_.sample(static_cast<double>(index) / animation_fps);
        v.message = "Player 1 shoots";
    }
    return v;
}

Grid BreakScene::grid(int index, int width, int height) const {
    return render(view(index), make_layout(table_, width, height), caps, width, height);
}

} // namespace termpool::tui
