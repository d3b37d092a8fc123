// The registry of game types: a row for every game, names that read back, and a game that is
// not one of termpool's, added here with its own referee and played through Game.
#include <catch2/catch.hpp>
#include <cmath>
#include <termpool/game_registry.hpp>
#include <termpool/referee.hpp>
#include <termpool/setup.hpp>
#include <termpool/snooker_layout.hpp>

#include "rules_helpers.hpp"

using namespace termpool;
using namespace termpool::test;

namespace {

// Every game type the enum has (snooker is its last).
std::vector<GameType> all_game_types() {
    std::vector<GameType> types;
    for (int t = 0; t <= static_cast<int>(GameType::snooker); ++t)
        types.push_back(static_cast<GameType>(t));
    return types;
}

// "Last ball", a game termpool does not have: any ball may be hit first, a ball down keeps the
// table, a foul hands it over with ball in hand anywhere, and whoever pots the last ball wins.
// The referee counts each player's pots on its score sheet's fouls line, for the test to read.
class LastBallReferee final : public RefereeOf<LastBallReferee> {
public:
    void new_rack(const GameState&) override { pots_[0] = pots_[1] = 0; }
    void set_up(const GameState& s, const ScoreSheet&) override { new_rack(s); }
    std::vector<int> legal_targets(const GameState& s) const override {
        std::vector<int> on;
        for (const Ball& b : s.balls)
            if (b.id != 0 && b.state != MotionState::pocketed)
                on.push_back(b.id);
        std::ranges::sort(on);
        return on;
    }
    bool pocket_must_be_called(const GameState&, int) const override { return false; }
    Verdict judge(GameState& s, const ShotCall&, const ShotFacts& facts) override {
        Verdict v;
        s.is_break = false;
        if (facts.dropped(0) || facts.first_contact < 0)
            v.fouls = {facts.dropped(0) ? Foul::scratch : Foul::no_contact};
        if (!v.fouls.empty()) {
            s.shooter = GameState::opponent(s.shooter);
            s.ball_in_hand = BallInHand::anywhere;
            return v;
        }
        for (const int id : facts.pocketed)
            pots_[s.shooter - 1] += id != 0;
        if (legal_targets(s).empty())
            s.win(s.shooter, WinReason::frame_won);
        else if (!facts.object_ball_dropped())
            s.shooter = GameState::opponent(s.shooter);
        return v;
    }
    void choose(GameState&, int, Choice) override {}
    ScoreSheet score_sheet(const GameState&) const override {
        ScoreSheet sheet;
        sheet.fouls_in_a_row[0] = pots_[0];
        sheet.fouls_in_a_row[1] = pots_[1];
        return sheet;
    }

private:
    int pots_[2] = {0, 0};
};

constexpr GameType last_ball_game{42};

GameRow last_ball_row() {
    GameRow row;
    row.type = last_ball_game;
    row.name = "lastball";
    row.other_names = {"last-ball"};
    row.title = "last ball";
    row.rack = RackType::nine_ball;
    row.make_referee = [] { return std::unique_ptr<Referee>(std::make_unique<LastBallReferee>()); };
    return row;
}

} // namespace

TEST_CASE("every game type has a row, and its names read back", "[registry]") {
    const GameRegistry& registry = game_registry();
    REQUIRE(registry.rows().size() == all_game_types().size());
    for (const GameType type : all_game_types()) {
        const GameRow* row = registry.find(type);
        REQUIRE(row);
        INFO(row->name);
        CHECK(row->make_referee);
        CHECK(std::string(row->title) != "");
        CHECK(parse_game_type(game_type_name(type)) == type);
        for (const std::string& other : row->other_names)
            CHECK(parse_game_type(other) == type);
        CHECK(&game_row(type) == row);
        CHECK(game_rack(type) == row->rack);
        // A new game of the type is the row's: its rack, its break.
        const Game game(type, nine_foot(), PhysicsParams{});
        CHECK(game.type() == type);
        CHECK(game.ball_in_hand() == row->break_from);
    }
    // Every spelling accepted before the registry still is.
    CHECK(parse_game_type("8ball") == GameType::eight_ball);
    CHECK(parse_game_type("8ball-bar") == GameType::eight_ball_bar);
    CHECK(parse_game_type("9ball") == GameType::nine_ball);
    CHECK(parse_game_type("10ball") == GameType::ten_ball);
    CHECK(parse_game_type("ten-ball") == GameType::ten_ball);
    CHECK(parse_game_type("10-ball") == GameType::ten_ball);
    CHECK(parse_game_type("snooker") == GameType::snooker);
    CHECK_FALSE(parse_game_type("8-ball"));
    CHECK_FALSE(parse_game_type(""));
    CHECK(std::string(game_type_name(last_ball_game)) == "?");
}

TEST_CASE("the rows say what differs between the games", "[registry]") {
    const GameRow& snooker = game_row(GameType::snooker);
    CHECK(snooker.table == TableSize::snooker);
    CHECK(table_played({GameType::snooker, TableSize::seven_foot, {}}) == TableSize::snooker);
    CHECK(table_played({GameType::nine_ball, TableSize::seven_foot, {}}) == TableSize::seven_foot);
    CHECK(snooker.scoring == Scoring::points);
    CHECK(std::string(snooker.words.unit) == "frame");
    CHECK(snooker.stats == StatsKind::snooker);
    CHECK(game_row(GameType::nine_ball).deciding_ball == 9);
    CHECK(game_row(GameType::ten_ball).deciding_ball == 10);
    CHECK(game_row(GameType::eight_ball_bar).deciding_ball == 8);
    CHECK(game_row(GameType::nine_ball).stats == StatsKind::pool);
    // The rotation games: the push-out after the break, no groups, fouls in a row counted.
    for (const GameType type : all_game_types()) {
        const GameRow& row = game_row(type);
        const bool rotation = type == GameType::nine_ball || type == GameType::ten_ball;
        CHECK(row.push_out == rotation);
        CHECK(row.groups == (type == GameType::eight_ball || type == GameType::eight_ball_bar));
        CHECK((row.panel.player == PlayerLine::fouls_in_a_row) == rotation);
    }
    CHECK(std::string(game_row(GameType::eight_ball).words.unit) == "rack");
    // The registry cycles through the games in order.
    CHECK(game_registry().next(GameType::eight_ball).type == GameType::eight_ball_bar);
    CHECK(game_registry().next(GameType::snooker).type == GameType::eight_ball);
}

TEST_CASE("a row's call rule is what its referee asks of a shot after the break",
          "[registry][rules]") {
    for (const GameType type : all_game_types()) {
        const GameRow& row = game_row(type);
        INFO(row.name);
        const Game game = Game::from_position(type, nine_foot(), PhysicsParams{},
                                              spread({0, 1, 2, 8, 9, 10}), 1, Group::open, false);
        for (const int ball : {1, 8, 9, 10}) {
            const bool called = row.calls == CallRule::every_pot ||
                                (row.calls == CallRule::deciding_ball && ball == row.deciding_ball);
            CHECK(game.pocket_must_be_called(ball) == called);
        }
        CHECK(game.nomination_owed() == false); // a snooker frame on a red names nothing
    }
}

TEST_CASE("a call fits the game's balls and pockets", "[registry]") {
    const GameRow& pool = game_row(GameType::eight_ball);
    const GameRow& snooker = game_row(GameType::snooker);
    CHECK(call_fits(pool, {15, 6, false}));
    CHECK_FALSE(call_fits(pool, {16, 6, false}));
    CHECK_FALSE(call_fits(pool, {3, 0, false}));
    CHECK(call_fits(snooker, {snooker_black, 0, false}));
    CHECK_FALSE(call_fits(snooker, {snooker_black + 1, 1, false}));
    CHECK_FALSE(call_fits(snooker, {0, 1, false}));
}

TEST_CASE("the default break: full at the head ball, or clipping the end red",
          "[registry][break]") {
    SECTION("pool: straight up the table at the apex") {
        const Game game(GameType::nine_ball, nine_foot(), PhysicsParams{}, 1, 3);
        const GameRow& row = game_row(GameType::nine_ball);
        CHECK(row.default_break.speed == 12.0);
        const double a = break_aim_deg(row, game.balls(), ball_radius);
        CHECK(std::abs(a) < 0.1); // the rack's balls sit a hair off their spots
        const auto apex = std::ranges::find(game.balls(), 1, &Ball::id);
        const Vec2 to = apex->position - game.balls().front().position;
        CHECK(std::atan2(to.y, to.x) * 180 / std::numbers::pi == Approx(a).margin(1e-9));
    }
    SECTION("snooker: the line passes the end red's centre at break_clip radii") {
        const GameSetup setup{GameType::snooker, TableSize::snooker, {}};
        const Game game = make_game(setup, 1, 5);
        const GameRow& row = game_row(GameType::snooker);
        const double R = game.params().ball_radius;
        CHECK(row.default_break.speed < 5.0);
        const double a = break_aim_deg(row, game.balls(), R) * std::numbers::pi / 180;
        const Vec2 dir{std::cos(a), std::sin(a)};
        const Vec2 cue = game.balls().front().position;
        double nearest = 1e9;
        for (const Ball& b : game.balls()) {
            if (!is_snooker_red(b.id))
                continue;
            const Vec2 to = b.position - cue;
            nearest = std::min(nearest, std::abs(to.x * dir.y - to.y * dir.x));
        }
        // A hair less than break_clip R: the aim point is break_clip R across the line to the
        // red's centre, so the line to it passes the centre at that times the cosine between.
        CHECK(nearest == Approx(break_clip * R).epsilon(1e-3));
    }
}

TEST_CASE("a game added in a test file is played through Game", "[registry][rules]") {
    GameRegistry registry = GameRegistry::standard();
    REQUIRE(registry.add(last_ball_row()));
    // Its type and its names are its own now.
    CHECK_FALSE(registry.add(last_ball_row()));
    GameRow taken = last_ball_row();
    taken.type = GameType{43};
    taken.other_names = {"9ball"};
    CHECK_FALSE(registry.add(taken));
    CHECK(registry.find("last-ball") == registry.find(last_ball_game));
    CHECK(registry.next(GameType::snooker).type == last_ball_game);
    CHECK_FALSE(game_registry().find(last_ball_game)); // the standard games are untouched

    const GameRow& row = *registry.find(last_ball_game);
    Game game(row, nine_foot(), PhysicsParams{}, 2, 11);
    CHECK(game.type() == last_ball_game);
    CHECK(game.shooter() == 2);
    CHECK(game.legal_targets() == std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9});
    CHECK_FALSE(game.pocket_must_be_called(1));

    // A real break, judged by the fake referee: whatever dropped keeps the table.
    ShotResult result;
    const Verdict brk = game.play({12.0, 0, 0, 0}, {}, &result);
    REQUIRE(brk.foul == Foul::none);
    const auto dropped = std::ranges::count_if(brk.pocketed, [](int id) { return id != 0; });
    CHECK(brk.next_shooter == (dropped > 0 ? 2 : 1));
    CHECK(game.consecutive_fouls(2) == dropped); // its pots, on its score sheet

    // Copies keep their own referee: a copy that pots the rest wins, the original does not.
    Game copy = game;
    const int shooter = copy.shooter(), pots_before = copy.consecutive_fouls(shooter);
    std::vector<Event> events{hit(0, copy.legal_targets().front())};
    int pocket = 1;
    for (const int id : copy.legal_targets())
        events.push_back(drop(id, pocket++ % 6 + 1));
    const Verdict last = copy.apply({}, hand_made(copy, events));
    CHECK(last.winner == shooter);
    CHECK(last.reason == WinReason::frame_won);
    CHECK(copy.consecutive_fouls(shooter) == pots_before + static_cast<int>(events.size()) - 1);
    CHECK(game.winner() == 0);
    CHECK(game.consecutive_fouls(2) == dropped);
}
