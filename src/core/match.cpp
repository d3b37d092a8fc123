// The flow of a match: who acts, what they may do, each action checked and recorded.
#include <cmath>
#include <termpool/match.hpp>

namespace termpool {

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
        return "the strike is out of range";
    case MatchError::bad_call:
        return "no such ball or pocket to call";
    case MatchError::not_offered:
        return "that choice is not on offer";
    case MatchError::bad_name:
        return "a name is 1 to 80 bytes of text, without control characters or spaces at the ends";
    case MatchError::bad_race:
        return "a race is 1 to 99 racks";
    case MatchError::started:
        return "the match has begun";
    }
    return "?";
}

bool valid_player_name(std::string_view name) {
    if (name.empty() || name.size() > max_player_name_bytes || name.front() == ' ' ||
        name.back() == ' ')
        return false;
    for (std::size_t i = 0; i < name.size();) {
        const auto byte = static_cast<unsigned char>(name[i]);
        // The sequence length from the lead byte; overlong forms and surrogates are refused.
        const std::size_t length = byte < 0x80                   ? 1
                                   : byte >= 0xC2 && byte < 0xE0 ? 2
                                   : byte >= 0xE0 && byte < 0xF0 ? 3
                                   : byte >= 0xF0 && byte < 0xF5 ? 4
                                                                 : 0;
        if (length == 0 || i + length > name.size())
            return false;
        char32_t code = length == 1 ? byte : byte & (0x7F >> length);
        for (std::size_t k = 1; k < length; ++k) {
            const auto next = static_cast<unsigned char>(name[i + k]);
            if ((next & 0xC0) != 0x80)
                return false;
            code = (code << 6) | (next & 0x3F);
        }
        const char32_t lowest[] = {0, 0, 0x80, 0x800, 0x10000};
        if (code < lowest[length] || code > 0x10FFFF || (code >= 0xD800 && code < 0xE000))
            return false;
        if (code < 0x20 || (code >= 0x7F && code < 0xA0))
            return false;
        i += length;
    }
    return true;
}

bool strike_in_range(const Strike& s) {
    return std::isfinite(s.speed) && std::isfinite(s.angle_deg) && std::isfinite(s.side) &&
           std::isfinite(s.follow) && s.speed >= 0 && s.speed <= max_strike_speed &&
           std::abs(s.side) <= 0.5 && std::abs(s.follow) <= 0.5;
}

Match::Match(const GameRecord& header, std::uint64_t computer_seed)
    : record_(header),
      game_(make_game(header.setup, header.breaker, header.seed)), score_{header.race_to,
                                                                          header.break_rule,
                                                                          {0, 0}},
      rack_breaker_(header.breaker), computer_seed_(computer_seed) {
    record_.actions.clear();
    for (int p = 1; p <= 2; ++p)
        seat_computer(p, header.computers[p - 1]);
}

std::variant<Match, RecordError> Match::replay(const GameRecord& record, std::size_t actions,
                                               const ShotListener& on_shot,
                                               std::uint64_t computer_seed) {
    Match m(record, computer_seed);
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
    return p.player != 0 && p.kind != Pending::next_rack && computers_[p.player - 1].has_value();
}

int Match::next_breaker() const {
    return game_.winner() == 0 ? 0 : score_.next_breaker(rack_breaker_, game_.winner());
}

bool Match::calls_pocket(int ball) const {
    if (game_.is_break())
        return false;
    switch (game_.type()) {
    case GameType::eight_ball:
        return true;
    case GameType::eight_ball_bar:
        return ball == 8;
    case GameType::nine_ball:
        return false;
    }
    return false;
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
    placed_ = true;
    RecordedAction action;
    action.kind = RecordedAction::Kind::place;
    action.place = spot;
    record_.actions.push_back(action);
    return MatchError::none;
}

std::variant<PlayedShot, MatchError> Match::shoot(int player, const Strike& strike,
                                                  const ShotCall& call, Trajectory* trajectory) {
    if (const MatchError e = check_player(player); e != MatchError::none)
        return e;
    const Pending kind = pending().kind;
    if ((kind != Pending::place && kind != Pending::shoot) || !game_.ready_to_shoot())
        return MatchError::not_now;
    if (!strike_in_range(strike))
        return MatchError::bad_strike;
    if (call.call.ball < 0 || call.call.ball > 15 || call.call.pocket < 0 || call.call.pocket > 6)
        return MatchError::bad_call;
    PlayedShot shot{game_.shooter(), rack_, game_.is_break(), game_.call_as_taken(call), {}, {}};
    shot.result = simulate_shot(game_.table(), game_.params(), game_.balls(), strike, trajectory);
    shot.verdict = game_.apply(call, shot.result);
    RecordedAction action;
    action.strike = strike;
    action.call = call;
    record_.actions.push_back(action);
    tally_.on_shot(shot.shooter, shot.was_break, shot.call, shot.verdict);
    placed_ = false;
    count_rack();
    return shot;
}

MatchError Match::choose(int player, Choice choice) {
    if (const MatchError e = check_player(player); e != MatchError::none)
        return e;
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
    const std::size_t before = record_.actions.size();
    MatchError error = MatchError::none;
    switch (action.kind) {
    case RecordedAction::Kind::place:
        error = place(to_act(), action.place);
        break;
    case RecordedAction::Kind::choose:
        error = choose(to_act(), action.choice);
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
        }
        break;
    }
    if (error == MatchError::none)
        record_.actions[before] = action; // as given: its seed, its line in the file
    return error;
}

std::optional<ComputerMove> Match::computer_move() {
    const PendingAction p = pending();
    if (!computer_to_act())
        return std::nullopt;
    ComputerPlayer& computer = *computers_[p.player - 1];
    ComputerMove move;
    move.kind = p.kind;
    if (p.kind == Pending::place)
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
