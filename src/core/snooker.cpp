// Snooker: WPBSA rules, as far as a simulator can judge them. The referee keeps the score
// sheet; what it cannot see (a push stroke, a jump shot, the intent behind a miss) it judges
// by the simplest reading of the rule, as the README says.
#include <algorithm>
#include <cmath>
#include <termpool/random.hpp>
#include <termpool/snooker_layout.hpp>
#include <termpool/spots.hpp>

#include "shot_facts.hpp"

namespace termpool {
namespace {

// The cue ball rests against a ball when the gap is below a tenth of a millimetre: the
// simulator leaves balls that rolled together a hair apart.
constexpr double touching_gap = 1e-4;

const Ball* on_table(const std::vector<Ball>& balls, int id) {
    for (const Ball& b : balls)
        if (b.id == id && b.state != MotionState::pocketed)
            return &b;
    return nullptr;
}

int reds_on(const std::vector<Ball>& balls) {
    return static_cast<int>(std::ranges::count_if(balls, [](const Ball& b) {
        return is_snooker_red(b.id) && b.state != MotionState::pocketed;
    }));
}

int lowest_colour(const std::vector<Ball>& balls) {
    for (int id = snooker_yellow; id <= snooker_black; ++id)
        if (on_table(balls, id))
            return id;
    return 0;
}

// True when the cue ball, moving from `from` along the unit vector `dir` for `travel` metres,
// would meet a ball other than the cue ball and those of `ignore`.
bool path_blocked(const std::vector<Ball>& balls, Vec2 from, Vec2 dir, double travel,
                  const std::vector<int>& ignore, double R) {
    for (const Ball& b : balls) {
        if (b.id == 0 || b.state == MotionState::pocketed || std::ranges::count(ignore, b.id) > 0)
            continue;
        const double u = std::clamp(dot(b.position - from, dir), 0.0, travel);
        if (length_squared(from + dir * u - b.position) < 4 * R * R)
            return true;
    }
    return false;
}

} // namespace

bool snookered(const std::vector<Ball>& balls, Vec2 cue, const std::vector<int>& on, double R) {
    bool any = false;
    for (const int id : on) {
        const Ball* b = on_table(balls, id);
        if (!b)
            continue;
        any = true;
        const Vec2 to = b->position - cue;
        const double d = length(to);
        if (d <= 2 * R + touching_gap)
            return false; // touching: it can be played away from, never snookered
        // The lines on which the cue ball just grazes either edge: turned from the line of
        // centres by the angle whose sine is 2R/d (a hair less, to make a contact).
        const double s = (2 * R - 1e-6) / d;
        const double c = std::sqrt(1 - s * s);
        const Vec2 u = to * (1 / d);
        const Vec2 n = perpendicular(u);
        const double travel = d * c;
        bool clear = true;
        for (const double side : {1.0, -1.0}) {
            const Vec2 dir = u * c + n * (side * s);
            if (path_blocked(balls, cue, dir, travel, on, R))
                clear = false;
        }
        if (clear)
            return false;
    }
    return any;
}

std::vector<int> Game::balls_on() const {
    std::vector<int> on;
    switch (snooker_.ball_on) {
    case BallOn::red:
        for (int id = snooker_first_red; id <= snooker_last_red; ++id)
            if (ball_on_table(id))
                on.push_back(id);
        break;
    case BallOn::colour:
        for (int id = snooker_yellow; id <= snooker_black; ++id)
            if (ball_on_table(id))
                on.push_back(id);
        break;
    case BallOn::in_order:
        if (const int id = lowest_colour(balls_); id != 0)
            on.push_back(id);
        break;
    }
    return on;
}

std::vector<int> Game::snooker_targets(const ShotCall& call) const {
    const int called = call.call.safety ? 0 : call.call.ball;
    if (snooker_.free_ball) {
        // A nominated free ball must be hit first (or at once with a ball on, which then counts
        // as hitting it); without a nomination any ball may be the free ball.
        if (called > 0 && ball_on_table(called))
            return {called};
        return legal_targets();
    }
    if (snooker_.ball_on == BallOn::colour && is_snooker_colour(called) && ball_on_table(called))
        return {called};
    return balls_on();
}

bool Game::snookered_by(int id) const {
    // The player now on (the turn has passed) is snookered, and would not be without `id`.
    const Ball* cue = on_table(balls_, 0);
    if (!cue)
        return false;
    std::vector<int> on;
    if (reds_on(balls_) > 0) {
        for (int red = snooker_first_red; red <= snooker_last_red; ++red)
            if (ball_on_table(red))
                on.push_back(red);
    } else if (const int lowest = lowest_colour(balls_); lowest != 0) {
        on.push_back(lowest);
    }
    const double R = params_.ball_radius;
    if (!snookered(balls_, cue->position, on, R))
        return false;
    std::vector<Ball> without = balls_;
    for (Ball& b : without)
        if (b.id == id)
            b.state = MotionState::pocketed;
    return !snookered(without, cue->position, on, R);
}

int Game::touching_ball() const {
    const Ball* cue = on_table(balls_, 0);
    if (type_ != GameType::snooker || !cue)
        return -1;
    const double R = params_.ball_radius;
    for (const int id : balls_on()) {
        const Ball* b = on_table(balls_, id);
        if (b && length(b->position - cue->position) <= 2 * R + touching_gap)
            return id;
    }
    return -1;
}

bool Game::shooter_snookered() const {
    const Ball* cue = on_table(balls_, 0);
    return type_ == GameType::snooker && cue &&
           snookered(balls_, cue->position, balls_on(), params_.ball_radius);
}

int Game::points_remaining() const {
    if (type_ != GameType::snooker)
        return 0;
    int colours = 0;
    for (int id = snooker_yellow; id <= snooker_black; ++id)
        if (ball_on_table(id))
            colours += snooker_value(id);
    const int reds = reds_on(balls_);
    // On a colour after a red the black is still worth taking once more.
    const int extra = snooker_.ball_on == BallOn::colour ? 7 : 0;
    return reds > 0 || snooker_.ball_on != BallOn::in_order ? 8 * reds + 27 + extra : colours;
}

bool Game::concede(int player) {
    if (type_ != GameType::snooker || winner_ != 0 || (player != 1 && player != 2))
        return false;
    end_visit();
    chooser_ = 0;
    choices_.clear();
    free_ball_offered_ = false;
    winner_ = opponent(player);
    reason_ = WinReason::conceded;
    return true;
}

void Game::end_visit() {
    int& highest = snooker_.highest_break[shooter_ - 1];
    highest = std::max(highest, snooker_.current_break);
    snooker_.current_break = 0;
}

void Game::respot_colours(std::vector<int> ids) {
    // The highest colour first, so that it gets its own spot when two want the same one.
    std::ranges::sort(ids, std::greater<>());
    for (const int id : ids) {
        const Vec2 spot = snooker_respot(table_, balls_, id, params_.ball_radius);
        for (Ball& b : balls_)
            if (b.id == id)
                set_at_rest(b, spot);
    }
}

void Game::end_frame(Verdict& v) {
    end_visit();
    const int a = snooker_.scores[0], b = snooker_.scores[1];
    if (a != b) {
        winner_ = a > b ? 1 : 2;
        reason_ = WinReason::frame_won;
        return;
    }
    v.respotted = {snooker_black};
    // Level: the black is re-spotted, lots are drawn for who plays first, from the D.
    snooker_.respotted_black = true;
    snooker_.ball_on = BallOn::in_order;
    snooker_.free_ball = false;
    respot_colours({snooker_black});
    Random lots(seed_ ^ 0x6c6f7473ULL); // "lots"
    shooter_ = 1 + static_cast<int>(lots.below(2));
    ball_in_hand_ = BallInHand::d;
    chooser_ = 0;
    choices_.clear();
}

Verdict Game::judge_snooker(const ShotCall& shot, const Facts& facts) {
    Verdict v;
    const int me = shooter_, other = opponent(shooter_);
    SnookerState& s = snooker_;
    const BallOn on = s.ball_on;
    const bool free = s.free_ball;
    s.free_ball = false;
    is_break_ = false;
    const std::vector<Ball>& before = before_shot_.balls;
    auto was_on_table = [&](int id) { return id > 0 && on_table(before, id) != nullptr; };
    const int lowest = lowest_colour(before);

    // The nomination: the colour called, or the first colour hit; the free ball likewise.
    const int called = shot.call.safety ? 0 : shot.call.ball;
    int nominated = 0;
    if (on == BallOn::colour) {
        if (is_snooker_colour(called) && was_on_table(called))
            nominated = called;
        else if (is_snooker_colour(facts.first_contact))
            nominated = facts.first_contact;
    }
    auto really_on = [&](int id) {
        switch (on) {
        case BallOn::red:
            return is_snooker_red(id);
        case BallOn::colour:
            return id != 0 && id == nominated;
        case BallOn::in_order:
            return id != 0 && id == lowest;
        }
        return false;
    };
    int free_ball = 0;
    if (free) {
        auto other_ball = [&](int id) { return was_on_table(id) && !really_on(id); };
        if (other_ball(called))
            free_ball = called;
        else if (called == 0 && other_ball(facts.first_contact))
            free_ball = facts.first_contact;
    }
    auto is_on = [&](int id) { return really_on(id) || (free_ball != 0 && id == free_ball); };
    // A free ball named before the shot must be the first ball hit.
    const bool free_ball_named = free_ball != 0 && free_ball == called;
    v.nominated = on == BallOn::colour ? nominated : free_ball;

    // Fouls, and their value: the ball on or the ball concerned, the higher, at least 4.
    const int on_value = on == BallOn::red      ? 1
                         : on == BallOn::colour ? snooker_value(nominated)
                                                : snooker_value(lowest);
    int penalty = std::max(4, on_value);
    auto concerned = [&](int id) {
        penalty = std::max(penalty, id == free_ball ? on_value : snooker_value(id));
    };
    if (facts.dropped(0))
        v.fouls.push_back(Foul::scratch);
    if (facts.left_table(0))
        v.fouls.push_back(Foul::cue_off_table);
    for (const int id : facts.off_table) {
        if (id == 0)
            continue;
        if (std::ranges::count(v.fouls, Foul::off_table) == 0)
            v.fouls.push_back(Foul::off_table);
        concerned(id);
    }
    const bool touching_on = facts.touching >= 0;
    if (facts.first_contact < 0) {
        if (!touching_on) // playing away from a touching ball on is deemed to hit it
            v.fouls.push_back(Foul::no_contact);
    } else if (!is_on(facts.first_contact) ||
               (free_ball_named && facts.first_contact != free_ball)) {
        v.fouls.push_back(Foul::wrong_ball_first);
        concerned(facts.first_contact);
    }
    std::vector<int> potted;
    for (const int id : facts.pocketed)
        if (id != 0)
            potted.push_back(id);
    for (const int id : potted) {
        if (!is_on(id)) {
            if (std::ranges::count(v.fouls, Foul::pot_not_on) == 0)
                v.fouls.push_back(Foul::pot_not_on);
            concerned(id);
        }
    }
    std::vector<int> colours_down;
    for (const int id : potted)
        if (is_snooker_colour(id))
            colours_down.push_back(id);
    for (const int id : facts.off_table)
        if (is_snooker_colour(id))
            colours_down.push_back(id);
    const bool last_black = on == BallOn::in_order && lowest == snooker_black;

    // A free ball that scores nothing and leaves the opponent snookered by it on every ball
    // on is a foul, except when only the pink and the black are left.
    auto down = [&](int id) { return id != 0 && std::ranges::count(potted, id) > 0; };
    const bool scores = on == BallOn::red
                            ? std::ranges::any_of(potted, is_snooker_red) || down(free_ball)
                        : on == BallOn::colour ? down(nominated)
                                               : down(lowest) || down(free_ball);
    const bool pink_and_black = reds_on(before) == 0 && lowest == snooker_pink;
    if (v.fouls.empty() && free_ball != 0 && !scores && !pink_and_black &&
        snookered_by(free_ball)) {
        v.fouls.push_back(Foul::free_ball_snooker);
        concerned(free_ball);
    }

    if (!v.fouls.empty()) {
        // After a red, a foul before any colour is nominated (nothing hit, or a red first, with
        // no colour named) costs seven.
        if (on == BallOn::colour && nominated == 0)
            penalty = 7;
        v.penalty = penalty;
        s.scores[other - 1] += penalty;
        end_visit();
        shooter_ = other;
        if (facts.dropped(0) || facts.left_table(0))
            ball_in_hand_ = BallInHand::d;
        if (last_black) {
            end_frame(v);
            return v;
        }
        // Colours potted on a foul come back; reds stay down.
        respot_colours(colours_down);
        v.respotted = colours_down;
        std::ranges::sort(v.respotted, std::greater<>());
        s.ball_on = reds_on(balls_) > 0 ? BallOn::red : BallOn::in_order;
        const bool failed_to_hit = std::ranges::count(v.fouls, Foul::no_contact) +
                                       std::ranges::count(v.fouls, Foul::wrong_ball_first) >
                                   0;
        v.miss = failed_to_hit && !facts.snookered_before && !touching_on;
        // Three misses in a row, the balls replaced each time, lose the frame.
        s.misses[me - 1] = v.miss ? s.misses[me - 1] + 1 : 0;
        if (s.misses[me - 1] >= 3) {
            winner_ = other;
            reason_ = WinReason::three_misses;
            return v;
        }
        chooser_ = other;
        choices_ = {Choice::play_on, Choice::offender_plays};
        if (v.miss)
            choices_.push_back(Choice::replace_and_replay);
        free_ball_offered_ = ball_in_hand_ == BallInHand::none && shooter_snookered();
        v.free_ball = free_ball_offered_;
        return v;
    }

    int points = 0;
    bool respot_free = false;
    switch (on) {
    case BallOn::red:
        points = static_cast<int>(std::ranges::count_if(potted, is_snooker_red));
        if (free_ball != 0 && std::ranges::count(potted, free_ball) > 0) {
            ++points; // the free ball counts as a red
            respot_free = true;
        }
        break;
    case BallOn::colour:
        if (std::ranges::count(potted, nominated) > 0)
            points = snooker_value(nominated);
        break;
    case BallOn::in_order:
        if (std::ranges::count(potted, lowest) > 0 ||
            (free_ball != 0 && std::ranges::count(potted, free_ball) > 0))
            points = snooker_value(lowest); // the free ball is worth the ball on
        respot_free = free_ball != 0 && std::ranges::count(potted, free_ball) > 0;
        break;
    }
    // While reds remain (and for the colour after the last red) potted colours come back; in
    // the colours' sequence only a free ball does.
    std::vector<int> respot;
    for (const int id : colours_down)
        if (on != BallOn::in_order || (respot_free && id == free_ball))
            respot.push_back(id);
    respot_colours(respot);
    v.respotted = respot;
    s.misses[me - 1] = 0;
    s.scores[me - 1] += points;
    s.current_break += points;
    v.points = points;
    if (points == 0) {
        end_visit();
        shooter_ = other;
        s.ball_on = reds_on(balls_) > 0 ? BallOn::red : BallOn::in_order;
        return v;
    }
    switch (on) {
    case BallOn::red:
        s.ball_on = BallOn::colour;
        break;
    case BallOn::colour:
        s.ball_on = reds_on(balls_) > 0 ? BallOn::red : BallOn::in_order;
        break;
    case BallOn::in_order:
        if (last_black && std::ranges::count(potted, snooker_black) > 0)
            end_frame(v);
        break;
    }
    return v;
}

} // namespace termpool
