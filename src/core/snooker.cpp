// Snooker: WPBSA rules, as far as a simulator can judge them. The referee keeps the score
// sheet; what it cannot see (a push stroke, a jump shot, the intent behind a miss) it judges
// by the simplest reading of the rule, as the README says.
#include "../support/random.hpp"
#include "../support/state_digest.hpp"
#include <algorithm>
#include <cmath>
#include <termpool/snooker_layout.hpp>
#include <termpool/spots.hpp>

#include "referees.hpp"
#include "snooker_referee.hpp"

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

std::unique_ptr<Referee> make_snooker_referee() {
    return std::make_unique<SnookerReferee>();
}

void SnookerReferee::new_rack(const GameState&) {
    frame_ = {};
    free_ball_offered_ = false;
}

void SnookerReferee::set_up(const GameState&, const ScoreSheet& sheet) {
    frame_ = sheet.frame;
    free_ball_offered_ = false;
}

ScoreSheet SnookerReferee::score_sheet(const GameState&) const {
    ScoreSheet sheet;
    sheet.frame = frame_;
    return sheet;
}

void SnookerReferee::add_to_digest(StateDigest& d) const {
    const SnookerState& f = frame_;
    for (const int v : {f.scores[0], f.scores[1], f.current_break, f.highest_break[0],
                        f.highest_break[1], static_cast<int>(f.ball_on)})
        d.add(v);
    d.add(f.free_ball);
    d.add(f.respotted_black);
    d.add(free_ball_offered_);
    d.add(f.misses[0]);
    d.add(f.misses[1]);
}

std::vector<int> SnookerReferee::balls_on(const GameState& s) const {
    std::vector<int> on;
    switch (frame_.ball_on) {
    case BallOn::red:
        for (int id = snooker_first_red; id <= snooker_last_red; ++id)
            if (s.on_table(id))
                on.push_back(id);
        break;
    case BallOn::colour:
        for (int id = snooker_yellow; id <= snooker_black; ++id)
            if (s.on_table(id))
                on.push_back(id);
        break;
    case BallOn::in_order:
        if (const int id = lowest_colour(s.balls); id != 0)
            on.push_back(id);
        break;
    }
    return on;
}

std::vector<int> SnookerReferee::legal_targets(const GameState& s) const {
    if (!frame_.free_ball)
        return balls_on(s);
    std::vector<int> on_table;
    for (const Ball& b : s.balls)
        if (b.id != 0 && b.state != MotionState::pocketed)
            on_table.push_back(b.id);
    std::ranges::sort(on_table);
    return on_table;
}

std::vector<int> SnookerReferee::shot_targets(const GameState& s, const ShotCall& call) const {
    const int called = call.call.safety ? 0 : call.call.ball;
    if (frame_.free_ball) {
        // A nominated free ball must be hit first (or at once with a ball on, which then counts
        // as hitting it); without a nomination any ball may be the free ball.
        if (called > 0 && s.on_table(called))
            return {called};
        return legal_targets(s);
    }
    if (frame_.ball_on == BallOn::colour && is_snooker_colour(called) && s.on_table(called))
        return {called};
    return balls_on(s);
}

bool SnookerReferee::pocket_must_be_called(const GameState&, int) const {
    return false; // the ball on is nominated, never its pocket
}

bool SnookerReferee::nomination_owed(const GameState&) const {
    return frame_.ball_on == BallOn::colour || frame_.free_ball;
}

void SnookerReferee::before_shot(const GameState& s) {
    before_shot_ = {s.balls, s.ball_in_hand, frame_, touching_ball(s), shooter_snookered(s)};
}

bool SnookerReferee::snookered_by(const GameState& s, int id) const {
    // The player now on (the turn has passed) is snookered, and would not be without `id`.
    const Ball* cue = on_table(s.balls, 0);
    if (!cue)
        return false;
    std::vector<int> on;
    if (reds_on(s.balls) > 0) {
        for (int red = snooker_first_red; red <= snooker_last_red; ++red)
            if (s.on_table(red))
                on.push_back(red);
    } else if (const int lowest = lowest_colour(s.balls); lowest != 0) {
        on.push_back(lowest);
    }
    const double R = s.params.ball_radius;
    if (!snookered(s.balls, cue->position, on, R))
        return false;
    std::vector<Ball> without = s.balls;
    for (Ball& b : without)
        if (b.id == id)
            b.state = MotionState::pocketed;
    return !snookered(without, cue->position, on, R);
}

int SnookerReferee::touching_ball(const GameState& s) const {
    const Ball* cue = on_table(s.balls, 0);
    if (!cue)
        return -1;
    const double R = s.params.ball_radius;
    for (const int id : balls_on(s)) {
        const Ball* b = on_table(s.balls, id);
        if (b && length(b->position - cue->position) <= 2 * R + touching_gap)
            return id;
    }
    return -1;
}

bool SnookerReferee::shooter_snookered(const GameState& s) const {
    const Ball* cue = on_table(s.balls, 0);
    return cue && snookered(s.balls, cue->position, balls_on(s), s.params.ball_radius);
}

int SnookerReferee::points_remaining(const GameState& s) const {
    int colours = 0;
    for (int id = snooker_yellow; id <= snooker_black; ++id)
        if (s.on_table(id))
            colours += snooker_value(id);
    const int reds = reds_on(s.balls);
    // On a colour after a red the black is still worth taking once more.
    const int extra = frame_.ball_on == BallOn::colour ? 7 : 0;
    return reds > 0 || frame_.ball_on != BallOn::in_order ? 8 * reds + 27 + extra : colours;
}

bool SnookerReferee::concede(GameState& s, int player) {
    end_visit(s);
    s.chooser = 0;
    s.choices.clear();
    free_ball_offered_ = false;
    s.win(GameState::opponent(player), WinReason::conceded);
    return true;
}

void SnookerReferee::choose(GameState& s, int who, Choice choice) {
    const int offender = GameState::opponent(who);
    const bool free_ball = free_ball_offered_;
    free_ball_offered_ = false;
    switch (choice) {
    case Choice::play_on:
        s.shooter = who;
        s.is_break = false;
        frame_.free_ball = free_ball;
        frame_.misses[offender - 1] = 0; // the three-miss count needs the balls replaced
        break;
    case Choice::offender_plays:
        s.shooter = offender;
        frame_.misses[offender - 1] = 0;
        break;
    case Choice::replace_and_replay:
        // The foul's points stay given; the balls and the ball on go back as they were.
        s.balls = before_shot_.balls;
        s.ball_in_hand = before_shot_.ball_in_hand;
        frame_.ball_on = before_shot_.frame.ball_on;
        frame_.free_ball = before_shot_.frame.free_ball;
        s.shooter = offender;
        break;
    default:
        break; // never offered
    }
}

void SnookerReferee::end_visit(const GameState& s) {
    int& highest = frame_.highest_break[s.shooter - 1];
    highest = std::max(highest, frame_.current_break);
    frame_.current_break = 0;
}

void SnookerReferee::respot_colours(GameState& s, std::vector<int> ids) const {
    // The highest colour first, so that it gets its own spot when two want the same one.
    std::ranges::sort(ids, std::greater<>());
    for (const int id : ids) {
        const Vec2 spot = snooker_respot(s.table, s.balls, id, s.params.ball_radius);
        for (Ball& b : s.balls)
            if (b.id == id)
                set_at_rest(b, spot);
    }
}

void SnookerReferee::end_frame(GameState& s, Verdict& v) {
    end_visit(s);
    const int a = frame_.scores[0], b = frame_.scores[1];
    if (a != b) {
        s.win(a > b ? 1 : 2, WinReason::frame_won);
        return;
    }
    v.respotted = {snooker_black};
    // Level: the black is re-spotted, lots are drawn for who plays first, from the D.
    frame_.respotted_black = true;
    frame_.ball_on = BallOn::in_order;
    frame_.free_ball = false;
    respot_colours(s, {snooker_black});
    Random lots(s.seed ^ 0x6c6f7473ULL); // "lots"
    s.shooter = 1 + static_cast<int>(lots.below(2));
    s.ball_in_hand = BallInHand::d;
    s.chooser = 0;
    s.choices.clear();
}

Verdict SnookerReferee::judge(GameState& s, const ShotCall& shot, const ShotFacts& facts) {
    Verdict v;
    const int me = s.shooter, other = GameState::opponent(s.shooter);
    SnookerState& f = frame_;
    const BallOn on = f.ball_on;
    const bool free = f.free_ball;
    f.free_ball = false;
    s.is_break = false;
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
    const bool touching_on = before_shot_.touching >= 0;
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
        snookered_by(s, free_ball)) {
        v.fouls.push_back(Foul::free_ball_snooker);
        concerned(free_ball);
    }

    if (!v.fouls.empty()) {
        // After a red, a foul before any colour is nominated (nothing hit, or a red first, with
        // no colour named) costs seven.
        if (on == BallOn::colour && nominated == 0)
            penalty = 7;
        v.penalty = penalty;
        f.scores[other - 1] += penalty;
        end_visit(s);
        s.shooter = other;
        if (facts.dropped(0) || facts.left_table(0))
            s.ball_in_hand = BallInHand::d;
        if (last_black) {
            end_frame(s, v);
            return v;
        }
        // Colours potted on a foul come back; reds stay down.
        respot_colours(s, colours_down);
        v.respotted = colours_down;
        std::ranges::sort(v.respotted, std::greater<>());
        f.ball_on = reds_on(s.balls) > 0 ? BallOn::red : BallOn::in_order;
        const bool failed_to_hit = std::ranges::count(v.fouls, Foul::no_contact) +
                                       std::ranges::count(v.fouls, Foul::wrong_ball_first) >
                                   0;
        v.miss = failed_to_hit && !before_shot_.snookered && !touching_on;
        // Three misses in a row, the balls replaced each time, lose the frame.
        f.misses[me - 1] = v.miss ? f.misses[me - 1] + 1 : 0;
        if (f.misses[me - 1] >= 3) {
            s.win(other, WinReason::three_misses);
            return v;
        }
        s.chooser = other;
        s.choices = {Choice::play_on, Choice::offender_plays};
        if (v.miss)
            s.choices.push_back(Choice::replace_and_replay);
        free_ball_offered_ = s.ball_in_hand == BallInHand::none && shooter_snookered(s);
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
    respot_colours(s, respot);
    v.respotted = respot;
    f.misses[me - 1] = 0;
    f.scores[me - 1] += points;
    f.current_break += points;
    v.points = points;
    if (points == 0) {
        end_visit(s);
        s.shooter = other;
        f.ball_on = reds_on(s.balls) > 0 ? BallOn::red : BallOn::in_order;
        return v;
    }
    switch (on) {
    case BallOn::red:
        f.ball_on = BallOn::colour;
        break;
    case BallOn::colour:
        f.ball_on = reds_on(s.balls) > 0 ? BallOn::red : BallOn::in_order;
        break;
    case BallOn::in_order:
        if (last_black && std::ranges::count(potted, snooker_black) > 0)
            end_frame(s, v);
        break;
    }
    return v;
}

} // namespace termpool
