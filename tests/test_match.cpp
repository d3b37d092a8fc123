// The Match: whole games and races played through it alone, every refused action leaving it
// unchanged, and a replay to any action giving the state the live match had there.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <termpool/computer.hpp>
#include <termpool/match.hpp>

#include "match_helpers.hpp"

using namespace termpool;
using termpool::test::play_computer_move;
using termpool::test::started;

namespace {

GameRecord header_for(GameType game, std::uint64_t seed, int race_to = 1) {
    GameRecord header;
    header.setup.game = game;
    header.seed = seed;
    header.names[0] = "Ann";
    header.names[1] = "Bob";
    header.computers[0] = Level::hard;
    header.computers[1] = Level::medium;
    header.race_to = race_to;
    return header;
}

// What a front end sees of a match, to compare a replay with the live match.
struct Seen {
    std::vector<Ball> balls;
    Pending pending;
    int to_act;
    MatchState score;
    int rack;
    std::array<PlayerStats, 2> figures;
    std::uint64_t hash;
    bool operator==(const Seen&) const = default;
};

Seen seen(const Match& m) {
    return {m.game().balls(), m.pending().kind, m.to_act(),    m.score(),
            m.rack(),         m.tally().both(), m.state_hash()};
}

} // namespace

TEST_CASE("whole games play through the Match alone and replay to every action", "[match]") {
    for (const GameType game : {GameType::eight_ball, GameType::eight_ball_bar, GameType::nine_ball,
                                GameType::ten_ball}) {
        INFO(game_type_name(game));
        Match match = started(header_for(game, 21), 5);
        std::vector<Seen> states{seen(match)};
        int guard = 0;
        while (match.pending().kind != Pending::over && ++guard < 400) {
            REQUIRE(match.computer_to_act());
            REQUIRE(play_computer_move(match) == MatchError::none);
            states.push_back(seen(match));
        }
        REQUIRE(match.pending().kind == Pending::over);
        CHECK(match.to_act() == 0);
        CHECK(match.game().winner() != 0);
        CHECK(match.score().match_winner() == match.game().winner());
        CHECK(match.tally().of(match.game().winner()).racks_won == 1);
        // Every action went into the record, and a replay up to any action sees what the live
        // match saw then.
        const GameRecord& record = match.record();
        REQUIRE(record.actions.size() + 1 == states.size());
        // The digest tells the states apart: every action changes it.
        for (std::size_t k = 1; k < states.size(); ++k)
            CHECK(states[k].hash != states[k - 1].hash);
        // Each action reads back from its line as the hall sends it.
        for (const RecordedAction& a : record.actions) {
            const auto back = parse_action(format_action(a));
            REQUIRE(std::holds_alternative<RecordedAction>(back));
            CHECK(format_action(std::get<RecordedAction>(back)) == format_action(a));
        }
        for (std::size_t k = 0; k < states.size(); k += 1 + k / 8) {
            const auto replayed = Match::replay(record, k);
            REQUIRE(std::holds_alternative<Match>(replayed));
            CHECK(seen(std::get<Match>(replayed)) == states[k]);
        }
        const auto parsed = parse_record(format_record(record));
        REQUIRE(std::holds_alternative<GameRecord>(parsed));
        const auto whole = Match::replay(std::get<GameRecord>(parsed));
        REQUIRE(std::holds_alternative<Match>(whole));
        CHECK(seen(std::get<Match>(whole)) == states.back());
        // Once over, nothing more is taken.
        CHECK(match.shoot(1, Strike{2, 0, 0, 0}, {}).index() == 1);
        CHECK(match.place(1, match.table().head_spot()) == MatchError::over);
    }
}

TEST_CASE("a race racks each next rack through the Match, for whoever the break rule says",
          "[match][race]") {
    Match match = started(header_for(GameType::nine_ball, 8, 2), 3);
    int guard = 0, racks_seen = 1;
    while (match.pending().kind != Pending::over && ++guard < 1500) {
        if (match.pending().kind == Pending::next_rack) {
            const int breaker = match.next_breaker();
            CHECK(match.to_act() == breaker);
            CHECK(breaker ==
                  match.score().next_breaker(match.rack_breaker(), match.game().winner()));
            CHECK_FALSE(
                match.computer_to_act()); // the next rack waits for a person, or a front end
            CHECK(match.next_rack(3) == MatchError::wrong_player);
            CHECK(match.next_rack(breaker) == MatchError::none);
            ++racks_seen;
            CHECK(match.rack() == racks_seen);
            CHECK(match.rack_breaker() == breaker);
            CHECK(match.pending().kind == Pending::place);
            CHECK(match.record().actions.back().kind == RecordedAction::Kind::rack);
            continue;
        }
        REQUIRE(play_computer_move(match) == MatchError::none);
    }
    REQUIRE(match.pending().kind == Pending::over);
    CHECK(match.score().match_winner() != 0);
    CHECK(match.score().racks_won[match.score().match_winner() - 1] == 2);
    CHECK(racks_seen == match.score().racks_played());
    CHECK(match.next_rack(1) == MatchError::over);
}

TEST_CASE("the Match says what it waits for and refuses every other action unchanged", "[match]") {
    GameRecord header = header_for(GameType::eight_ball, 4);
    header.computers[0].reset();
    header.computers[1].reset();
    header.breaker = 2;
    Match match = started(header);
    const Seen before = seen(match);
    const auto unchanged = [&](MatchError got, MatchError want) {
        CHECK(got == want);
        CHECK(match.record().actions.empty());
        CHECK(seen(match) == before);
    };

    // The break: player 2 has the cue ball in hand in the kitchen.
    PendingAction now = match.pending();
    CHECK(now.kind == Pending::place);
    CHECK(now.player == 2);
    CHECK(now.ball_in_hand == BallInHand::kitchen);
    CHECK_FALSE(match.computer_to_act());
    CHECK_FALSE(match.computer_move());
    CHECK_FALSE(match.calls_pocket(3)); // the break calls nothing

    const Vec2 kitchen = match.table().head_spot();
    const Vec2 beyond{match.table().length * 0.75, match.table().width / 2};
    unchanged(match.place(1, kitchen), MatchError::wrong_player);
    unchanged(match.place(0, kitchen), MatchError::wrong_player);
    unchanged(match.place(2, beyond), MatchError::illegal_spot);
    unchanged(match.choose(2, Choice::play_on), MatchError::not_now);
    unchanged(match.next_rack(2), MatchError::not_now);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const Strike bad : {Strike{25, 0, 0, 0}, Strike{-1, 0, 0, 0}, Strike{5, nan, 0, 0},
                             Strike{5, 0, 0.6, 0}, Strike{5, 0, 0, -0.51}}) {
        const auto shot = match.shoot(2, bad, {});
        REQUIRE(std::holds_alternative<MatchError>(shot));
        unchanged(std::get<MatchError>(shot), MatchError::bad_strike);
    }
    // Only calls the record can say: a ball 1-15 into a pocket 1-6, or none.
    for (const Call bad : {Call{16, 1, false}, Call{5, 0, false}, Call{0, 3, false},
                           Call{-1, 1, false}, Call{5, 7, false}}) {
        ShotCall silly;
        silly.call = bad;
        unchanged(std::get<MatchError>(match.shoot(2, Strike{10, 0, 0, 0}, silly)),
                  MatchError::bad_call);
    }
    unchanged(std::get<MatchError>(match.shoot(1, Strike{10, 0, 0, 0}, {})),
              MatchError::wrong_player);

    // Names and the race are checked too.
    CHECK(match.rename(1, "Ann Lee") == MatchError::none);
    CHECK(match.name(1) == "Ann Lee");
    for (const char* bad : {"", " Ann", "Ann ", "A\nB", "A\x1b[2JB", "\xc3", "\xc2\x85"})
        CHECK(match.rename(2, bad) == MatchError::bad_name);
    CHECK(match.rename(2, std::string(81, 'x')) == MatchError::bad_name);
    CHECK(match.rename(2, "Bjørn") == MatchError::none);
    CHECK(match.rename(3, "Cy") == MatchError::wrong_player);
    CHECK(match.set_race(0) == MatchError::bad_race);
    CHECK(match.set_race(max_race_to + 1) == MatchError::bad_race);
    CHECK(match.set_race(3) == MatchError::none);
    CHECK(match.score().race_to == 3);

    // Placed: the break is the shot now; the race can no longer change. Putting the ball down
    // again this turn replaces the spot in the record.
    CHECK(match.place(2, kitchen + Vec2{-0.1, 0.05}) == MatchError::none);
    CHECK(match.place(2, kitchen) == MatchError::none);
    REQUIRE(match.record().actions.size() == 1);
    CHECK(match.record().actions[0].place == kitchen);
    CHECK(match.pending().kind == Pending::shoot);
    CHECK(match.set_race(5) == MatchError::started);
    const auto broke = match.shoot(2, Strike{12, 0, 0, 0}, {});
    REQUIRE(std::holds_alternative<PlayedShot>(broke));
    const PlayedShot& shot = std::get<PlayedShot>(broke);
    CHECK(shot.shooter == 2);
    CHECK(shot.was_break);
    CHECK(shot.rack == 1);
    CHECK_FALSE(shot.result.events.empty());
    CHECK(shot.result.balls == match.game().balls());
    CHECK(match.record().actions.size() == 2);
    CHECK(match.tally().of(2).shots == 1);
    // After the break, 8-ball calls every pocket.
    if (match.pending().kind == Pending::shoot)
        CHECK(match.calls_pocket(3));
}

TEST_CASE("a computer seated in a match decides for its seat only", "[match]") {
    GameRecord header = header_for(GameType::nine_ball, 9);
    header.computers[0].reset(); // a person breaks, the computer waits
    Match match = started(header, 1);
    CHECK(match.seat(1).name == "Ann");
    CHECK_FALSE(match.seat(1).computer);
    CHECK(match.seat(2).computer == Level::medium);
    CHECK_FALSE(match.computer_to_act());
    CHECK_FALSE(match.computer_move());
    CHECK(match.seat_computer(1, Level::easy) == MatchError::none);
    CHECK(match.computer_to_act());
    const auto move = match.computer_move();
    REQUIRE(move);
    CHECK(move->kind == Pending::place);
    CHECK(match.game().legal_placement(move->spot));
    CHECK(match.seat_computer(3, Level::easy) == MatchError::wrong_player);
}

TEST_CASE("a record edited into an impossible state is refused at its line", "[match][record]") {
    Match match = started(header_for(GameType::eight_ball, 2), 1);
    REQUIRE(play_computer_move(match) == MatchError::none); // the placement
    REQUIRE(play_computer_move(match) == MatchError::none); // the break
    GameRecord record = match.record();
    RecordedAction wild;
    wild.strike = Strike{40, 0, 0, 0};
    wild.line = 17;
    if (match.pending().kind == Pending::choose) {
        wild.kind = RecordedAction::Kind::choose;
        wild.choice = Choice::pass_back;
    }
    record.actions.push_back(wild);
    const auto replayed = Match::replay(record);
    REQUIRE(std::holds_alternative<RecordError>(replayed));
    CHECK(std::get<RecordError>(replayed).line == 17);
    // A prefix that stops before the bad action is fine.
    CHECK(std::holds_alternative<Match>(Match::replay(record, record.actions.size() - 1)));
}

TEST_CASE("a match starts only from a header a record can keep", "[match]") {
    const auto refused = [](GameRecord header) {
        const auto m = Match::start(header);
        return std::holds_alternative<MatchError>(m) ? std::get<MatchError>(m) : MatchError::none;
    };
    GameRecord good = header_for(GameType::eight_ball, 1);
    CHECK(refused(good) == MatchError::none);
    GameRecord h = good;
    h.breaker = 3;
    CHECK(refused(h) == MatchError::wrong_player);
    h = good;
    h.names[1] = "Bob\nplace 0 0";
    CHECK(refused(h) == MatchError::bad_name);
    h = good;
    h.race_to = max_race_to + 1;
    CHECK(refused(h) == MatchError::bad_race);
    h = good;
    h.setup.physics.gravity = 1.6; // the moon: a record could not say so
    CHECK(refused(h) == MatchError::bad_setup);
    h = good;
    h.setup.physics.friction = FrictionModel{FrictionKind::decay, 0, 0};
    CHECK(refused(h) == MatchError::bad_setup);
    h = good;
    h.setup.physics.friction = FrictionModel{FrictionKind::combined, 0.5, 0.25};
    h.setup.physics.cue_ball_mass = 0.2;
    CHECK(refused(h) == MatchError::none);
}

TEST_CASE("every shot a match takes survives its record's text", "[match][record]") {
    Match match = started(header_for(GameType::eight_ball, 3), 2);
    ShotCall safety;
    safety.call = {5, 2, true}; // a safety names no ball: the record keeps only "safety"
    REQUIRE(play_computer_move(match) == MatchError::none); // the placement
    REQUIRE(std::holds_alternative<PlayedShot>(match.shoot(match.to_act(), {12, 0, 0, 0}, safety)));
    CHECK(match.record().actions.back().call.call.ball == 0);
    for (int i = 0; i < 6 && match.pending().kind != Pending::over; ++i)
        REQUIRE(play_computer_move(match) == MatchError::none);
    const auto parsed = parse_record(format_record(match.record()));
    REQUIRE(std::holds_alternative<GameRecord>(parsed));
    CHECK(format_record(std::get<GameRecord>(parsed)) == format_record(match.record()));
    const auto again = Match::replay(std::get<GameRecord>(parsed));
    REQUIRE(std::holds_alternative<Match>(again));
    CHECK(seen(std::get<Match>(again)) == seen(match));
}

TEST_CASE("a rematch keeps the seats, and the computers play on with their own streams",
          "[match]") {
    GameRecord header = header_for(GameType::nine_ball, 12);
    Match first = started(header, 40);
    // Seat 1's computer is seeded 40 + 1: `same` makes the same decisions beside it.
    ComputerPlayer same(Level::hard, 41);
    const auto place_and_shoot = [&](Match& m) {
        const auto place = m.computer_move();
        REQUIRE(place->kind == Pending::place);
        CHECK(place->spot == same.place_cue_ball(m.game()));
        REQUIRE(m.place(1, place->spot) == MatchError::none);
        const auto shot = m.computer_move();
        REQUIRE(shot->kind == Pending::shoot);
        return shot->shot.strike;
    };
    const Strike first_break = place_and_shoot(first);
    CHECK(first_break.speed == same.shot(first.game()).strike.speed);
    Match second = std::move(first).rematch(1, 99);
    CHECK(second.record().seed == 99);
    CHECK(second.record().actions.empty());
    CHECK(second.name(1) == "Ann");
    CHECK(second.seat(2).computer == Level::medium);
    CHECK(second.rack() == 1);
    // A fresh computer would break with its first noise; this one breaks with its next.
    ComputerPlayer fresh(Level::hard, 41);
    fresh.place_cue_ball(second.game());
    const Strike second_break = place_and_shoot(second);
    const Strike fresh_break = fresh.shot(second.game()).strike;
    const Strike continuing = same.shot(second.game()).strike;
    CHECK(second_break.speed == continuing.speed);
    CHECK(second_break.angle_deg == continuing.angle_deg);
    CHECK(second_break.angle_deg != fresh_break.angle_deg);
}

TEST_CASE("a strike with a negative zero is played as the record writes it", "[match][record]") {
    // The record writes -0 as "0"; the match plays the strike as written, so that the replay,
    // which reads +0, passes through the same bits.
    Match match = started(header_for(GameType::nine_ball, 5), 2);
    REQUIRE(play_computer_move(match) == MatchError::none); // the placement
    const double negative_zero = -0.0;
    const Strike strike{9, 1.5, negative_zero, negative_zero};
    REQUIRE(std::holds_alternative<PlayedShot>(match.shoot(match.to_act(), strike, {})));
    const Strike recorded = match.record().actions.back().strike;
    CHECK_FALSE(std::signbit(recorded.side));
    CHECK_FALSE(std::signbit(recorded.follow));
    const auto parsed = parse_record(format_record(match.record()));
    REQUIRE(std::holds_alternative<GameRecord>(parsed));
    const auto again = Match::replay(std::get<GameRecord>(parsed));
    REQUIRE(std::holds_alternative<Match>(again));
    CHECK(seen(std::get<Match>(again)) == seen(match));
}

TEST_CASE("10-ball: every shot after the break calls its pocket, and the computer calls",
          "[match][ten]") {
    int called = 0, choices = 0;
    for (const std::uint64_t seed : {3, 4, 5}) {
        GameRecord header = header_for(GameType::ten_ball, seed);
        header.computers[0] = Level::easy;
        header.computers[1] = Level::easy;
        Match match = started(header, seed);
        CHECK_FALSE(match.calls_pocket(1)); // the break calls nothing
        int guard = 0;
        while (match.pending().kind != Pending::over && ++guard < 400) {
            const PendingAction p = match.pending();
            if (p.kind == Pending::choose) {
                CHECK(p.choices == std::vector<Choice>{Choice::shoot, Choice::pass_back});
                ++choices;
            }
            if (p.kind == Pending::shoot && !match.game().is_break()) {
                CHECK(match.calls_pocket(1));
                CHECK(match.calls_pocket(10));
                const std::optional<ComputerMove> move = match.computer_move();
                REQUIRE(move);
                const Call& call = move->shot.call.call;
                // The computer names a ball and pocket (or safety) unless nothing could be
                // potted, when the referee takes the obvious call.
                called += call.safety || (call.ball >= 1 && call.pocket >= 1);
            }
            REQUIRE(play_computer_move(match) == MatchError::none);
        }
        REQUIRE(match.pending().kind == Pending::over);
        CHECK(match.game().win_reason() != WinReason::nine_pocketed);
        // The record replays to the same end, choices and all.
        const auto replayed = Match::replay(match.record());
        REQUIRE(std::holds_alternative<Match>(replayed));
        CHECK(std::get<Match>(replayed).state_hash() == match.state_hash());
    }
    CHECK(called > 0);
    INFO(choices << " choices after a ball down uncalled");
}
