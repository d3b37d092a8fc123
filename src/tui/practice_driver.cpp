#include "tui/practice_driver.hpp"

#include <algorithm>
#include <termpool/setup.hpp>

#include "tui/cell_step.hpp"
#include "tui/local_driver.hpp"

namespace termpool::tui {
namespace {

std::string ball_name(int id) {
    return id == 0 ? "cue ball" : std::to_string(id);
}

std::string potted_words(const ShotResult& result) {
    std::string s;
    for (const Event& e : result.events)
        if (e.kind == EventKind::pocket && e.ball != 0)
            s += " " + std::to_string(e.ball);
    return s.empty() ? "Nothing potted" : "Potted" + s;
}

} // namespace

PracticeDriver::PracticeDriver(const GameOptions& options, std::uint64_t seed)
    : table_(make_table(options.setup)), params_(game_physics(options.setup)), seed_(seed + 1),
      players_(first_match(options, seed)),
      // The rack a game would have.
      practice_(table_, params_, game_rack(options.setup.game), players_.record().seed),
      game_(players_.game()) {
    sync();
}

void PracticeDriver::sync() {
    // The rest of the App reads the table through a Game: one with no referee state.
    game_ = Game::from_position(players_.setup().game, table_, params_, practice_.balls(), 1,
                                Group::open, practice_.is_break());
}

std::vector<int> PracticeDriver::targets() const {
    std::vector<int> all; // no referee: every ball is fair
    for (const Ball& b : game_.balls())
        if (b.id != 0 && b.state != MotionState::pocketed)
            all.push_back(b.id);
    return all;
}

std::optional<TableNews> PracticeDriver::submit(const RecordedAction& action,
                                                std::string& refusal) {
    if (action.kind != RecordedAction::Kind::shot) {
        refusal = "practice has no referee";
        return std::nullopt;
    }
    last_strike_ = action.strike;
    TableNews news;
    news.action = action;
    news.actor = 1;
    news.before = game_;
    news.trajectory.emplace(params_, game_.balls().size());
    news.shot.emplace(); // no referee: the simulation alone
    news.shot->shooter = 1;
    news.shot->result = practice_.shoot(action.strike, &*news.trajectory);
    bool cue_potted = false;
    for (const Event& e : news.shot->result.events)
        cue_potted |= e.kind == EventKind::pocket && e.ball == 0;
    news.words = potted_words(news.shot->result) +
                 (cue_potted ? "; the cue ball is back on the head spot" : "") +
                 ". r takes the shot again, m moves a ball";
    sync();
    return news;
}

MatchError PracticeDriver::rename(int player, const std::string& name) {
    return players_.rename(player, name);
}

std::string PracticeDriver::table_words() const {
    return "Practice: no referee. m moves a ball, r takes a shot again, t racks again";
}

std::optional<DriverReply> PracticeDriver::handle(const Input& in, const Layout& layout,
                                                  const ScreenFacts& screen) {
    if (screen.rolling || screen.asking)
        return std::nullopt;
    if (moving_)
        return handle_moving(in, layout);
    if (in.kind != Input::Kind::text)
        return std::nullopt;
    if (in.text == "m") {
        moving_ = true;
        held_ = -1;
        return DriverReply{"Move a ball: click one or press Tab; Esc ends", false, {}};
    }
    if (in.text == "r") {
        if (!practice_.retake())
            return DriverReply{"No shot to take again", false, {}};
        sync();
        // The same aim, spin and elevation, ready to adjust.
        return DriverReply{"The balls are back: take the shot again", true, last_strike_};
    }
    if (in.text == "t") {
        practice_.rerack(seed_++);
        sync();
        return DriverReply{"A new rack", true, {}};
    }
    return std::nullopt;
}

DriverReply PracticeDriver::hold(int id) {
    held_ = id;
    held_at_ = table_.foot_spot();
    for (const Ball& b : practice_.balls())
        if (b.id == id && b.state != MotionState::pocketed)
            held_at_ = b.position;
    return {"Moving the " + ball_name(id) +
                ": arrows or the mouse move it, Enter or a click puts it down, Tab picks the "
                "next, Esc ends",
            false,
            {}};
}

DriverReply PracticeDriver::put_down(Vec2 spot) {
    if (!practice_.put(held_, spot))
        return {"The " + ball_name(held_) + " cannot go there: " +
                    (on_playing_surface(table_, spot, params_.ball_radius)
                         ? "it would touch another ball"
                         : "that is off the cloth"),
                false,
                {}};
    sync();
    const std::string put =
        "Put down the " + ball_name(held_) + ". Tab or a click picks another, Esc ends";
    held_ = -1;
    return {put, false, {}};
}

std::optional<DriverReply> PracticeDriver::handle_moving(const Input& in, const Layout& layout) {
    const int key = in.kind == Input::Kind::key ? in.key : 0;
    const std::string& text = in.kind == Input::Kind::text ? in.text : std::string();
    if (text == "q" || text == "?" || text == "l")
        return std::nullopt;
    if (in.kind == Input::Kind::mouse) {
        if (!layout.fits)
            return DriverReply{};
        const Vec2 pointer = from_cell(layout, table_.width, in.x, in.y);
        if (held_ >= 0) {
            held_at_ = pointer;
            return in.clicked || in.released ? put_down(pointer) : DriverReply{};
        }
        if (!(in.clicked || in.pressed))
            return DriverReply{};
        // The ball under the pointer: within a cell of its centre.
        const double reach = std::max(2 * params_.ball_radius, 1.5 / layout.cells_per_metre);
        int nearest = -1;
        double best = reach * reach;
        for (const Ball& b : practice_.balls())
            if (b.state != MotionState::pocketed && length_squared(b.position - pointer) <= best)
                best = length_squared(b.position - pointer), nearest = b.id;
        return nearest >= 0 ? hold(nearest) : DriverReply{};
    }
    if (key == key_escape || text == "m") {
        moving_ = false;
        held_ = -1;
        return DriverReply{"", true, {}};
    }
    if (key == '\t' || text == "]" || text == "[") {
        // Every ball, on the table or pocketed, in id order: a pocketed one comes back.
        std::vector<int> ids;
        for (const Ball& b : practice_.balls())
            ids.push_back(b.id);
        std::sort(ids.begin(), ids.end());
        const auto at = std::find(ids.begin(), ids.end(), held_);
        const int n = static_cast<int>(ids.size());
        const int i = at == ids.end() ? (text == "[" ? 0 : -1) : static_cast<int>(at - ids.begin());
        return hold(ids[static_cast<std::size_t>(((i + (text == "[" ? -1 : 1)) % n + n) % n)]);
    }
    if (held_ >= 0 && !step_spot(held_at_, key, text, layout, table_, params_.ball_radius, false) &&
        (key == key_enter || text == " "))
        return put_down(held_at_);
    return DriverReply{};
}

void PracticeDriver::compose(View& v, const ScreenFacts&) const {
    if (!moving_)
        return;
    // Moving balls, not aiming: no cue, no aid.
    v.aiming = false;
    v.show_aid = false;
    v.show_marker = false;
    if (held_ < 0)
        return;
    // Every ball is in the list, pocketed ones too: a pocketed one comes back to be placed.
    for (Ball& b : v.balls) {
        if (b.id != held_)
            continue;
        b.position = held_at_;
        b.state = MotionState::stationary;
    }
    // The cue ball shows a refused spot as in ball in hand.
    v.placing = held_ == 0;
    v.placement_legal = practice_.can_put(held_, held_at_);
}

} // namespace termpool::tui
