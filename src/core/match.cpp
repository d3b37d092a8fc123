// The flow of a match: who acts, what they may do, each action checked and recorded.
#include "../support/state_digest.hpp"
#include <algorithm>
#include <bit>
#include <cmath>
#include <string>
#include <termpool/game_registry.hpp>
#include <termpool/match.hpp>
#include <termpool/referee.hpp>

namespace termpool {

static_assert(max_race_to == 99, "match_error_text names the longest race");

const char* match_error_text(MatchError error) {
    switch (error) {
    case MatchError::none:
        return "done";
    case MatchError::over:
        return "the game is over";
    case MatchError::wrong_player:
        return "it is the other player's turn";
    case MatchError::not_now:
        return "the game waits for something else";
    case MatchError::illegal_spot:
        return "the cue ball cannot go there";
    case MatchError::bad_strike:
        return "the strike is out of range or would need a jump shot";
    case MatchError::bad_call:
        return "no such ball or pocket to call";
    case MatchError::not_offered:
        return "that choice is not on offer";
    case MatchError::bad_name:
        return "a name is text without control characters or spaces at the ends, and not too long";
    case MatchError::bad_race:
        return "a race is 1 to 99 racks";
    case MatchError::started:
        return "the match has begun";
    case MatchError::bad_setup:
        return "the breaker is 1 or 2, and the physics the defaults but for the cloth and the cue "
               "ball's mass";
    }
    return "?";
}

bool strike_in_range(const Strike& s) {
    return std::isfinite(s.speed) && std::isfinite(s.angle_deg) && std::isfinite(s.side) &&
           std::isfinite(s.follow) && std::isfinite(s.elevation_deg) && s.speed >= 0 &&
           s.speed <= max_strike_speed && std::abs(s.side) <= 0.5 && std::abs(s.follow) <= 0.5 &&
           s.elevation_deg >= 0 && s.elevation_deg <= max_cue_elevation_deg;
}

namespace {

// A record keeps the cloth model, the cue ball's mass and the cue: any other constant would be
// lost.
bool recordable(const PhysicsParams& p) {
    const PhysicsParams d;
    const FrictionModel& f = p.friction;
    const bool classic_constants_ok =
        f.kind == FrictionKind::physical ||
        ((f.kind == FrictionKind::constant || (std::isfinite(f.decay_rate) && f.decay_rate > 0)) &&
         (f.kind == FrictionKind::decay || (std::isfinite(f.deceleration) && f.deceleration > 0)));
    return classic_constants_ok && f.rest_speed == d.friction.rest_speed &&
           std::isfinite(p.cue_ball_mass) && p.cue_ball_mass >= 0 &&
           std::isfinite(p.cue_end_mass) && p.cue_end_mass >= 0 && p.ball_radius == d.ball_radius &&
           p.ball_mass == d.ball_mass && p.sliding_friction == d.sliding_friction &&
           p.rolling_friction == d.rolling_friction && p.spin_friction == d.spin_friction &&
           p.ball_restitution == d.ball_restitution && p.ball_friction == d.ball_friction &&
           p.cushion_restitution == d.cushion_restitution &&
           p.cushion_friction == d.cushion_friction &&
           p.cushion_height_ratio == d.cushion_height_ratio &&
           p.cushion_frequency_ratio == d.cushion_frequency_ratio && p.gravity == d.gravity &&
           p.elastic_below_speed == d.elastic_below_speed && p.collision == d.collision &&
           p.cushion == d.cushion;
}

} // namespace

std::variant<Match, MatchError> Match::start(const GameRecord& header,
                                             std::uint64_t computer_seed) {
    if (header.breaker != 1 && header.breaker != 2)
        return MatchError::wrong_player;
    if (header.race_to < 0 || header.race_to > max_race_to)
        return MatchError::bad_race;
    if (!valid_player_name(header.names[0]) || !valid_player_name(header.names[1]))
        return MatchError::bad_name;
    if (!recordable(header.setup.physics))
        return MatchError::bad_setup;
    return Match(header, computer_seed);
}

Match Match::rematch(int breaker, std::uint64_t seed) && {
    GameRecord header = record_;
    header.actions.clear();
    header.breaker = breaker == 2 ? 2 : 1;
    header.seed = seed;
    Match next(header, computer_seed_);
    for (int p = 0; p < 2; ++p)
        next.computers_[p] = std::move(computers_[p]);
    return next;
}

Match::Match(const GameRecord& header, std::uint64_t computer_seed)
    : record_(header),
      game_(make_game(header.setup, header.breaker, header.seed)), score_{header.race_to,
                                                                          header.break_rule,
                                                                          {0, 0}},
      rack_breaker_(header.breaker), tally_(header.setup.game), computer_seed_(computer_seed) {
    record_.actions.clear();
    record_.check.reset();
    record_.setup.table = table_played(header.setup); // snooker says so in its record
    for (int p = 1; p <= 2; ++p)
        seat_computer(p, header.computers[p - 1]);
}

std::variant<Match, RecordError> Match::replay(const GameRecord& record, std::size_t actions,
                                               const ShotListener& on_shot,
                                               std::uint64_t computer_seed) {
    auto replayed = replay_unchecked(record, actions, on_shot, computer_seed);
    if (!record.check)
        return replayed; // version 3 and older: nothing to compare with
    const RecordCheck& check = *record.check;
    const Match* m = std::get_if<Match>(&replayed);
    // A partial replay cannot see the end; the reader checks the whole record once on loading.
    // Versions 4 and 5 checked only the state the last action left.
    const auto ours = [&check](const Match& match) {
        return check.running ? match.check_hash() : match.final_check_hash();
    };
    if (m && (actions < record.actions.size() || ours(*m) == check.hash))
        return replayed;
    const int line = m ? check.line : std::get<RecordError>(replayed).line;
    if (check.physics_version != physics_version)
        return RecordError{line,
                           "made with physics version " + std::to_string(check.physics_version) +
                               ", which this termpool (physics version " +
                               std::to_string(physics_version) + ") replays into a different game"};
    if (m)
        return RecordError{line, "the replay does not end in the state the check names: the "
                                 "record was edited or damaged"};
    return replayed;
}

std::variant<Match, RecordError> Match::replay_unchecked(const GameRecord& record,
                                                         std::size_t actions,
                                                         const ShotListener& on_shot,
                                                         std::uint64_t computer_seed) {
    auto started = start(record, computer_seed);
    if (const MatchError* e = std::get_if<MatchError>(&started))
        return RecordError{0, match_error_text(*e)};
    Match& m = std::get<Match>(started);
    const std::size_t count = std::min(actions, record.actions.size());
    for (std::size_t i = 0; i < count; ++i) {
        const RecordedAction& a = record.actions[i];
        if (a.kind == RecordedAction::Kind::rack) {
            // The rack action stores its breaker: it must be the one the break rule gives.
            if (m.score_.match_winner() != 0)
                return RecordError{a.line, "the match is over: no rack follows"};
            if (m.game_.winner() == 0)
                return RecordError{a.line, "a rack starts only when the one before is won"};
            if (a.breaker != m.next_breaker())
                return RecordError{a.line, "player " + std::to_string(m.next_breaker()) +
                                               " breaks this rack (the " +
                                               break_rule_name(record.break_rule) + " rule)"};
        }
        PlayedShot shot;
        const MatchError error = m.apply(a, nullptr, &shot);
        if (error == MatchError::none) {
            if (a.kind == RecordedAction::Kind::shot && on_shot)
                on_shot(shot);
            continue;
        }
        switch (a.kind) {
        case RecordedAction::Kind::place:
            return RecordError{a.line, "the cue ball cannot be placed there now"};
        case RecordedAction::Kind::choose:
            return RecordError{a.line, std::string("'") + choice_name(a.choice) +
                                           "' is not a choice owed now"};
        case RecordedAction::Kind::shot:
            return RecordError{a.line,
                               error == MatchError::bad_strike || error == MatchError::bad_call
                                   ? std::string(match_error_text(error))
                                   : "no shot can be played now"};
        case RecordedAction::Kind::rack:
            return RecordError{a.line, match_error_text(error)};
        }
    }
    return m;
}

void Match::stamp_check(bool replaced_last) {
    static_assert(StateDigest().value() == empty_digest);
    if (!replaced_last)
        actions_digest_before_last_ = actions_digest_;
    // Each action's text and the state it led to, chained: a change anywhere moves every
    // later value, so a damaged action is caught even where the game comes back to the same
    // state (a 9-ball call naming another pocket, a cue ball placed elsewhere and potted).
    StateDigest d;
    d.add(actions_digest_before_last_);
    d.add(format_action(record_.actions.back()));
    d.add(state_hash());
    actions_digest_ = d.value();
    record_.check = RecordCheck{physics_version, check_hash(), 0, true};
}

std::uint64_t Match::check_hash() const {
    // The race is in the header, not in the actions: an edited race must not pass the check.
    StateDigest d;
    d.add(actions_digest_);
    d.add(score_.race_to);
    d.add(static_cast<int>(score_.break_rule));
    return d.value();
}

std::uint64_t Match::final_check_hash() const {
    StateDigest d;
    d.add(state_hash());
    d.add(score_.race_to);
    d.add(static_cast<int>(score_.break_rule));
    return d.value();
}

std::uint64_t Match::state_hash() const {
    StateDigest d;
    d.add(static_cast<std::uint64_t>(record_.actions.size()));
    d.add(rack_);
    d.add(rack_breaker_);
    d.add(score_.racks_won[0]);
    d.add(score_.racks_won[1]);
    d.add(placed_);
    const Game& g = game_;
    d.add(g.shooter());
    d.add(g.chooser());
    d.add(g.winner());
    d.add(static_cast<int>(g.win_reason()));
    d.add(static_cast<int>(g.ball_in_hand()));
    d.add(g.is_break());
    d.add(static_cast<int>(g.player1_group()));
    d.add(g.push_out_allowed());
    d.add(g.consecutive_fouls(1));
    d.add(g.consecutive_fouls(2));
    for (const Choice c : g.choices())
        d.add(static_cast<int>(c));
    // What else the referee keeps (snooker's frame); pool's referees add nothing more, so that
    // the hashes of pool games stay as they were.
    g.referee().add_to_digest(d);
    for (const Ball& b : g.balls()) {
        d.add(b.id);
        d.add(static_cast<int>(b.state));
        d.add(b.pocket);
        d.add(b.position.x);
        d.add(b.position.y);
    }
    return d.value();
}

Seat Match::seat(int player) const {
    const int p = player == 2 ? 1 : 0;
    return Seat{record_.names[p], record_.computers[p]};
}

PendingAction Match::pending() const {
    PendingAction p;
    if (score_.match_winner() != 0) {
        p.kind = Pending::over;
        return p;
    }
    if (game_.winner() != 0) {
        p.kind = Pending::next_rack;
        p.player = next_breaker();
        return p;
    }
    if (game_.chooser() != 0) {
        p.kind = Pending::choose;
        p.player = game_.chooser();
        p.choices = game_.choices();
        return p;
    }
    p.player = game_.shooter();
    p.ball_in_hand = game_.ball_in_hand();
    p.kind = p.ball_in_hand != BallInHand::none && !placed_ ? Pending::place : Pending::shoot;
    return p;
}

bool Match::computer_to_act() const {
    const PendingAction p = pending();
    return (p.player == 1 || p.player == 2) && p.kind != Pending::next_rack &&
           computers_[p.player - 1].has_value();
}

int Match::next_breaker() const {
    return game_.winner() == 0 ? 0 : score_.next_breaker(rack_breaker_, game_.winner());
}

bool Match::calls_pocket(int ball) const {
    return game_.pocket_must_be_called(ball);
}

MatchError Match::check_player(int player) const {
    const PendingAction p = pending();
    if (p.kind == Pending::over)
        return MatchError::over;
    if (player != p.player)
        return MatchError::wrong_player;
    return MatchError::none;
}

MatchError Match::place(int player, Vec2 spot) {
    if (const MatchError e = check_player(player); e != MatchError::none)
        return e;
    const PendingAction p = pending();
    if (p.kind != Pending::place && p.kind != Pending::shoot)
        return MatchError::not_now;
    if (p.ball_in_hand == BallInHand::none)
        return MatchError::not_now;
    if (!game_.place_cue_ball(spot))
        return MatchError::illegal_spot;
    RecordedAction action;
    action.kind = RecordedAction::Kind::place;
    action.place = spot;
    // Putting the cue ball down again this turn replaces the first spot: the record stays as
    // long as the game, however often a player moves the ball.
    const bool replaced = placed_ && !record_.actions.empty() &&
                          record_.actions.back().kind == RecordedAction::Kind::place;
    if (replaced)
        record_.actions.back() = action;
    else
        record_.actions.push_back(action);
    placed_ = true;
    stamp_check(replaced);
    return MatchError::none;
}

namespace {

// The record writes -0 as "0" (format_double), and a replay must play what was played: the
// sign of a zero can reach the spin through copysign.
Strike as_recorded(const Strike& s) {
    Strike out = s;
    for (double* v : {&out.speed, &out.angle_deg, &out.side, &out.follow, &out.elevation_deg})
        *v = *v == 0 ? 0.0 : *v;
    return out;
}

} // namespace

std::variant<PlayedShot, MatchError> Match::shoot(int player, const Strike& asked,
                                                  const ShotCall& call, Trajectory* trajectory) {
    const Strike strike = as_recorded(asked);
    if (const MatchError e = check_player(player); e != MatchError::none)
        return e;
    const Pending kind = pending().kind;
    if ((kind != Pending::place && kind != Pending::shoot) || !game_.ready_to_shoot())
        return MatchError::not_now;
    if (strike_problem(strike, game_.params()))
        return MatchError::bad_strike;
    // What the record can say: no call, a safety, or a ball into a pocket 1-6; where a call
    // names the ball on (snooker's nomination) its pocket may be none (0).
    ShotCall taken = call;
    if (taken.call.safety)
        taken.call.ball = taken.call.pocket = 0;
    if (!call_fits(game_row(game_.type()), taken.call) &&
        (taken.call.ball != 0 || taken.call.pocket != 0))
        return MatchError::bad_call;
    PlayedShot shot{game_.shooter(), rack_, game_.is_break(), game_.call_as_taken(taken), {}, {}};
    shot.result = simulate_shot(game_.table(), game_.params(), game_.balls(), strike, trajectory);
    shot.verdict = game_.apply(taken, shot.result);
    RecordedAction action;
    action.strike = strike;
    action.call = taken;
    record_.actions.push_back(action);
    tally_.on_shot(shot.shooter, shot.was_break, shot.call, shot.verdict);
    placed_ = false;
    count_rack();
    stamp_check();
    return shot;
}

MatchError Match::choose(int player, Choice choice) {
    if (const MatchError e = check_player(player); e != MatchError::none)
        return e;
    if (choice == Choice::concede)
        return concede(player); // never owed, but a player may always concede
    if (pending().kind != Pending::choose)
        return MatchError::not_now;
    if (!game_.choose(choice))
        return MatchError::not_offered;
    RecordedAction action;
    action.kind = RecordedAction::Kind::choose;
    action.choice = choice;
    record_.actions.push_back(action);
    placed_ = false;
    count_rack();
    stamp_check();
    return MatchError::none;
}

MatchError Match::concede(int player) {
    if (const MatchError e = check_player(player); e != MatchError::none)
        return e;
    const Pending kind = pending().kind;
    if (kind == Pending::next_rack)
        return MatchError::over;
    if (!game_.concede(player))
        return MatchError::not_offered;
    tally_.on_conceded(game_.winner());
    RecordedAction action;
    action.kind = RecordedAction::Kind::choose;
    action.choice = Choice::concede;
    record_.actions.push_back(action);
    placed_ = false;
    count_rack();
    stamp_check();
    return MatchError::none;
}

MatchError Match::next_rack(int player) {
    if (pending().kind == Pending::over)
        return MatchError::over;
    if (player != 1 && player != 2)
        return MatchError::wrong_player;
    if (pending().kind != Pending::next_rack)
        return MatchError::not_now;
    const RecordedAction rack = rack_action(record_, rack_ + 1, next_breaker());
    record_.actions.push_back(rack);
    start_rack(rack.breaker, rack.seed);
    stamp_check();
    return MatchError::none;
}

MatchError Match::rename(int player, std::string_view name) {
    if (player != 1 && player != 2)
        return MatchError::wrong_player;
    if (!valid_player_name(name))
        return MatchError::bad_name;
    record_.names[player - 1] = std::string(name);
    return MatchError::none;
}

MatchError Match::seat_computer(int player, std::optional<Level> level) {
    if (player != 1 && player != 2)
        return MatchError::wrong_player;
    record_.computers[player - 1] = level;
    computers_[player - 1].reset();
    if (level)
        computers_[player - 1].emplace(*level, computer_seed_ + static_cast<std::uint64_t>(player));
    return MatchError::none;
}

MatchError Match::set_race(int race_to) {
    if (!record_.actions.empty())
        return MatchError::started;
    if (race_to < 1 || race_to > max_race_to)
        return MatchError::bad_race;
    record_.race_to = race_to;
    score_.race_to = race_to;
    return MatchError::none;
}

MatchError Match::apply(const RecordedAction& action, Trajectory* trajectory, PlayedShot* shot) {
    MatchError error = MatchError::none;
    switch (action.kind) {
    case RecordedAction::Kind::place:
        error = place(to_act(), action.place);
        break;
    case RecordedAction::Kind::choose:
        error = choose(to_act(), action.choice); // a concession too
        break;
    case RecordedAction::Kind::shot: {
        auto played = shoot(to_act(), action.strike, action.call, trajectory);
        if (const MatchError* e = std::get_if<MatchError>(&played))
            error = *e;
        else if (shot)
            *shot = std::move(std::get<PlayedShot>(played));
        break;
    }
    case RecordedAction::Kind::rack:
        if (pending().kind != Pending::next_rack)
            error = pending().kind == Pending::over ? MatchError::over : MatchError::not_now;
        else if (action.breaker != next_breaker())
            error = MatchError::wrong_player;
        else {
            record_.actions.push_back(action);
            start_rack(action.breaker, action.seed);
            stamp_check();
        }
        break;
    }
    if (error == MatchError::none && action.kind != RecordedAction::Kind::shot)
        record_.actions.back() = action; // as given: its seed, its line in the file
    else if (error == MatchError::none)
        record_.actions.back().line = action.line;
    return error;
}

std::optional<ComputerMove> Match::computer_move() {
    const PendingAction p = pending();
    if (!computer_to_act())
        return std::nullopt;
    ComputerPlayer& computer = *computers_[p.player - 1];
    ComputerMove move;
    move.kind = p.kind;
    if (computer.concedes(game_)) {
        move.kind = Pending::choose;
        move.choice = Choice::concede;
    } else if (p.kind == Pending::place)
        move.spot = computer.place_cue_ball(game_);
    else if (p.kind == Pending::choose)
        move.choice = computer.choose(game_);
    else
        move.shot = computer.shot(game_);
    return move;
}

void Match::reseed_computers(std::uint64_t computer_seed) {
    computer_seed_ = computer_seed;
    for (int p = 1; p <= 2; ++p)
        seat_computer(p, record_.computers[p - 1]);
}

std::uint64_t Match::computer_simulations(int player) const {
    const auto& computer = computers_[player == 2 ? 1 : 0];
    return computer ? computer->simulations() : 0;
}

void Match::start_rack(int breaker, std::uint64_t seed) {
    game_ = make_game(record_.setup, breaker, seed);
    ++rack_;
    rack_breaker_ = breaker;
    rack_counted_ = false;
    placed_ = false;
}

void Match::count_rack() {
    // A rack counts once, when the action that won it has been played.
    if (!rack_counted_ && game_.winner() != 0)
        rack_counted_ = score_.record_rack(game_.winner());
}

} // namespace termpool
