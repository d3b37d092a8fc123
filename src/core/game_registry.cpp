// The game types, one row each. A new game is its referee's file and a row here.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <termpool/game_registry.hpp>

#include "../support/portable_math.hpp"
#include <termpool/break_off.hpp>
#include <termpool/referee.hpp>
#include <termpool/snooker_layout.hpp>

#include "referees.hpp"

namespace termpool {
namespace {

constexpr GameWords rack_words{};
constexpr GameWords frame_words{"frame",
                                "frames",
                                "next frame (the loser breaks off)",
                                "new frame",
                                "rematch (the loser breaks off)",
                                "breaks off",
                                "break-off",
                                "Frame"};
constexpr DefaultBreak pool_break{12.0, BreakAim::head_ball};
// Snooker breaks off softly, thin off the end red, so that the cue ball comes back to baulk.
constexpr DefaultBreak snooker_break{break_off_speed, BreakAim::end_red};

std::vector<GameRow> standard_rows() {
    return {
        {.type = GameType::eight_ball,
         .name = "8ball",
         .title = "8-ball",
         .rack = RackType::eight_ball,
         .deciding_ball = 8,
         .default_break = pool_break,
         .groups = true,
         .words = rack_words,
         .panel = {PlayerLine::group, PocketedLine::outside_groups},
         .stats = StatsKind::pool,
         .make_referee = make_eight_ball_referee},
        {.type = GameType::eight_ball_bar,
         .name = "8ball-bar",
         .title = "8-ball, bar rules",
         .rack = RackType::eight_ball,
         .deciding_ball = 8,
         .default_break = pool_break,
         .calls = CallRule::deciding_ball,
         .groups = true,
         .words = rack_words,
         .panel = {PlayerLine::group, PocketedLine::outside_groups},
         .stats = StatsKind::pool,
         .make_referee = make_bar_eight_ball_referee},
        {.type = GameType::nine_ball,
         .name = "9ball",
         .title = "9-ball",
         .rack = RackType::nine_ball,
         .deciding_ball = 9,
         .default_break = pool_break,
         .calls = CallRule::nothing,
         .push_out = true,
         .words = rack_words,
         .panel = {PlayerLine::fouls_in_a_row, PocketedLine::all},
         .stats = StatsKind::pool,
         .make_referee = make_nine_ball_referee},
        {.type = GameType::ten_ball,
         .name = "10ball",
         .other_names = {"ten-ball", "10-ball"},
         .title = "10-ball",
         .rack = RackType::ten_ball,
         .deciding_ball = 10,
         .default_break = pool_break,
         .push_out = true,
         .words = rack_words,
         .panel = {PlayerLine::fouls_in_a_row, PocketedLine::all},
         .stats = StatsKind::pool,
         .make_referee = make_ten_ball_referee},
        {.type = GameType::snooker,
         .name = "snooker",
         .title = "snooker",
         .table = TableSize::snooker,
         .rack = RackType::snooker,
         .balls = BallSet::snooker,
         .break_from = BallInHand::d,
         .default_break = snooker_break,
         .calls = CallRule::ball_on,
         .words = frame_words,
         .scoring = Scoring::points,
         .panel = {PlayerLine::highest_break, PocketedLine::none},
         .stats = StatsKind::snooker,
         .make_referee = make_snooker_referee},
    };
}

double degrees_of(Vec2 v) {
    return portable::atan2(v.y, v.x) * 180 / std::numbers::pi;
}

} // namespace

int last_ball(BallSet set) {
    return set == BallSet::snooker ? snooker_black : 15;
}

GameRegistry GameRegistry::standard() {
    GameRegistry registry;
    for (GameRow& row : standard_rows())
        registry.add(std::move(row));
    return registry;
}

bool GameRegistry::add(GameRow row) {
    if (!row.make_referee || find(row.type) || find(row.name))
        return false;
    for (const std::string& name : row.other_names)
        if (find(name))
            return false;
    rows_.push_back(std::move(row));
    return true;
}

const GameRow* GameRegistry::find(GameType type) const {
    const auto it = std::ranges::find(rows_, type, &GameRow::type);
    return it == rows_.end() ? nullptr : &*it;
}

const GameRow* GameRegistry::find(std::string_view name) const {
    for (const GameRow& row : rows_)
        if (name == row.name || std::ranges::count(row.other_names, name) > 0)
            return &row;
    return nullptr;
}

const GameRow& GameRegistry::next(GameType type) const {
    const auto it = std::ranges::find(rows_, type, &GameRow::type);
    return it == rows_.end() || it + 1 == rows_.end() ? rows_.front() : *(it + 1);
}

const GameRegistry& game_registry() {
    static const GameRegistry standard = GameRegistry::standard();
    return standard;
}

const GameRow& game_row(GameType type) {
    const GameRow* row = game_registry().find(type);
    return row ? *row : game_registry().rows().front();
}

const char* game_type_name(GameType type) {
    const GameRow* row = game_registry().find(type);
    return row ? row->name : "?";
}

std::optional<GameType> parse_game_type(const std::string& name) {
    const GameRow* row = game_registry().find(name);
    return row ? std::optional<GameType>(row->type) : std::nullopt;
}

bool call_fits(const GameRow& row, const Call& call) {
    return call.ball >= 1 && call.ball <= last_ball(row.balls) &&
           call.pocket >= (row.calls == CallRule::ball_on ? 0 : 1) && call.pocket <= 6;
}

double break_aim_deg(const GameRow& row, const std::vector<Ball>& balls, double ball_radius) {
    const auto cue = std::ranges::find(balls, 0, &Ball::id);
    if (cue == balls.end())
        return 0;
    const Vec2 from = cue->position;
    const Ball* target = nullptr;
    if (row.default_break.aim == BreakAim::head_ball) {
        // The object ball nearest the head of the table, full in the face.
        for (const Ball& b : balls)
            if (b.id != 0 && b.state != MotionState::pocketed &&
                (!target || b.position.x < target->position.x))
                target = &b;
        return target ? degrees_of(target->position - from) : 0;
    }
    // Snooker's break-off: thin off the end red of the pack on the cue ball's side.
    return break_off_aim_deg(balls, ball_radius, break_clip);
}

} // namespace termpool
