#include <algorithm>
#include <termpool/simulator.hpp>

#include "cloth_model.hpp"

namespace termpool {

Trajectory::Trajectory(PhysicsParams params, std::size_t ball_count)
    : params_(params), pieces_(ball_count) {}

void Trajectory::restart(const PhysicsParams& params) {
    params_ = params;
    for (std::vector<Piece>& list : pieces_)
        list.clear();
}

void Trajectory::add(std::size_t index, double start, const Ball& ball) {
    std::vector<Piece>& list = pieces_[index];
    // A later piece at the same instant replaces the earlier one (several events at one time).
    if (!list.empty() && list.back().start == start) {
        list.back().ball = ball;
        return;
    }
    list.push_back({start, ball});
}

namespace {

// The state at `time` of a ball whose pieces are `list` (not empty).
Ball state_at(const std::vector<Trajectory::Piece>& list, double time,
              const core::ClothModel& cloth, const PhysicsParams& params) {
    // The last piece that started at or before `time`.
    auto it = std::upper_bound(list.begin(), list.end(), time,
                               [](double t, const Trajectory::Piece& p) { return t < p.start; });
    const Trajectory::Piece& piece = it == list.begin() ? list.front() : *std::prev(it);
    const double limit = cloth.time_to_transition(piece.ball, params);
    const double dt = std::clamp(time - piece.start, 0.0, limit);
    return cloth.advance(piece.ball, dt, params);
}

} // namespace

std::vector<Ball> Trajectory::sample(double time) const {
    const core::ClothModel cloth = core::cloth_model(params_.friction);
    std::vector<Ball> out;
    out.reserve(pieces_.size());
    for (const std::vector<Piece>& list : pieces_)
        if (!list.empty())
            out.push_back(state_at(list, time, cloth, params_));
    return out;
}

Ball Trajectory::sample(std::size_t index, double time) const {
    return state_at(pieces_[index], time, core::cloth_model(params_.friction), params_);
}

Ball Trajectory::sample_before(std::size_t index, double time) const {
    const std::vector<Piece>& list = pieces_[index];
    // The last piece that started before `time`: a piece starting at `time` is the event's.
    auto it = std::lower_bound(list.begin(), list.end(), time,
                               [](const Piece& p, double t) { return p.start < t; });
    if (it == list.begin())
        return list.front().ball;
    const Piece& piece = *std::prev(it);
    const core::ClothModel cloth = core::cloth_model(params_.friction);
    const double limit = cloth.time_to_transition(piece.ball, params_);
    return cloth.advance(piece.ball, std::clamp(time - piece.start, 0.0, limit), params_);
}

std::optional<std::size_t> Trajectory::slot_of(int id) const {
    for (std::size_t i = 0; i < pieces_.size(); ++i)
        if (!pieces_[i].empty() && pieces_[i].front().ball.id == id)
            return i;
    return std::nullopt;
}

std::optional<EventState> event_state(const Trajectory& trajectory, const Event& event) {
    const auto slot = trajectory.slot_of(event.ball);
    if (!slot)
        return std::nullopt;
    EventState out{trajectory.sample_before(*slot, event.time),
                   trajectory.sample(*slot, event.time), std::nullopt, std::nullopt};
    if (event.kind == EventKind::ball_ball)
        if (const auto other = trajectory.slot_of(event.other)) {
            out.other_before = trajectory.sample_before(*other, event.time);
            out.other_after = trajectory.sample(*other, event.time);
        }
    return out;
}

} // namespace termpool
