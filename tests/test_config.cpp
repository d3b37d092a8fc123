// The config file: defaults for the game, with bad values refused at their line.
#include <catch2/catch.hpp>

#include "player/config.hpp"

using namespace termpool;

TEST_CASE("the config file sets the game's defaults", "[config]") {
    GameOptions o;
    std::vector<std::string> warnings;
    const auto error = apply_config("# my defaults\n"
                                    "player1 = Ann Lee\n"
                                    "  player2=Bob  \n"
                                    "game = 9ball\n"
                                    "table = 7ft\n"
                                    "power-mode = timed\n"
                                    "aim-aid = off\n"
                                    "level = pro\n",
                                    o, warnings);
    CHECK_FALSE(error);
    CHECK(warnings.empty());
    CHECK(o.names[0] == "Ann Lee");
    CHECK(o.names[1] == "Bob");
    CHECK(o.setup.game == GameType::nine_ball);
    CHECK(o.setup.table == TableSize::seven_foot);
    CHECK(o.timed_power);
    CHECK_FALSE(o.aim_aid);
    CHECK(o.default_level == Level::pro);
    // The command line still wins, and --vs-computer without a level takes the config's.
    std::string why;
    const auto parsed = parse_game_options({"--game", "8ball", "--vs-computer"}, why, o);
    REQUIRE(parsed);
    CHECK(parsed->setup.game == GameType::eight_ball);
    CHECK(parsed->computer == Level::pro);
}

TEST_CASE("unknown keys warn, bad values name their line", "[config]") {
    GameOptions o;
    std::vector<std::string> warnings;
    CHECK_FALSE(apply_config("colour = pink\n", o, warnings));
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].find(":1: unknown key 'colour'") != std::string::npos);

    const struct {
        const char* text;
        const char* says;
    } bad[] = {
        {"game = croquet\n", "1: unknown game 'croquet'"},
        {"\n\ntable = 12ft\n", "3: unknown table '12ft'"},
        {"power-mode = fast\n", "1: power-mode is distance or timed"},
        {"aim-aid = maybe\n", "1: aim-aid is on or off"},
        {"level = godlike\n", "1: unknown level 'godlike'"},
        {"player1 = A\x01z\n", "1: player1: "},
        {"just words\n", "1: expected 'key = value'"},
    };
    for (const auto& b : bad) {
        GameOptions fresh;
        std::vector<std::string> w;
        const auto error = apply_config(b.text, fresh, w);
        INFO(b.text);
        REQUIRE(error);
        CHECK(error->starts_with(b.says));
    }
}

TEST_CASE("a race and its break rule come from the command line or the config", "[config][race]") {
    std::string why;
    const auto single = parse_game_options({}, why);
    REQUIRE(single);
    CHECK(single->race_to == 1);
    CHECK(single->break_rule == BreakRule::alternate);

    const auto race = parse_game_options({"--race", "5", "--breaks", "winner"}, why);
    REQUIRE(race);
    CHECK(race->race_to == 5);
    CHECK(race->break_rule == BreakRule::winner);

    GameOptions o;
    std::vector<std::string> warnings;
    CHECK_FALSE(apply_config("race = 7\nbreaks = winner\n", o, warnings));
    CHECK(warnings.empty());
    CHECK(o.race_to == 7);
    CHECK(o.break_rule == BreakRule::winner);
    // The command line wins over the config.
    const auto over = parse_game_options({"--race", "1", "--breaks", "alternate"}, why, o);
    REQUIRE(over);
    CHECK(over->race_to == 1);
    CHECK(over->break_rule == BreakRule::alternate);
    const auto kept = parse_game_options({"--game", "9ball"}, why, o);
    REQUIRE(kept);
    CHECK(kept->race_to == 7);
}

TEST_CASE("bad races and break rules are refused", "[config][race]") {
    const struct {
        std::vector<std::string> args;
        const char* says;
    } bad[] = {
        {{"--race", "0"}, "--race takes a number of racks from 1 to 99, not '0'"},
        {{"--race", "100"}, "--race takes a number of racks from 1 to 99, not '100'"},
        {{"--race", "3x"}, "--race takes a number of racks from 1 to 99, not '3x'"},
        {{"--race", "-2"}, "--race takes a number of racks from 1 to 99, not '-2'"},
        {{"--race", ""}, "--race takes a number of racks from 1 to 99, not ''"},
        {{"--race"}, "--race needs a value"},
        {{"--breaks", "loser"}, "unknown break rule 'loser' (alternate or winner)"},
        {{"--breaks"}, "--breaks needs a value"},
    };
    for (const auto& b : bad) {
        std::string why;
        INFO(b.says);
        CHECK_FALSE(parse_game_options(b.args, why));
        CHECK(why == b.says);
    }
    const struct {
        const char* text;
        const char* says;
    } bad_config[] = {
        {"race = 0\n", "1: race is a number of racks from 1 to 99, not '0'"},
        {"\nrace = many\n", "2: race is a number of racks from 1 to 99, not 'many'"},
        {"race =\n", "1: race is a number of racks from 1 to 99, not ''"},
        {"breaks = loser\n", "1: breaks is alternate or winner, not 'loser'"},
    };
    for (const auto& b : bad_config) {
        GameOptions o;
        std::vector<std::string> w;
        const auto error = apply_config(b.text, o, w);
        INFO(b.text);
        REQUIRE(error);
        CHECK(*error == b.says);
        CHECK(o.race_to == 1);
    }
}

TEST_CASE("the snooker table from the command line or the config", "[config][snooker]") {
    std::string why;
    const auto parsed = parse_game_options({"--table", "snooker"}, why);
    REQUIRE(parsed);
    CHECK(parsed->setup.table == TableSize::snooker);
    // The balls follow the table in the game, not in the options: the record keeps defaults.
    CHECK(parsed->setup.physics.ball_radius == PhysicsParams{}.ball_radius);
    CHECK(game_physics(parsed->setup).ball_radius == 0.02625);
    GameOptions o;
    std::vector<std::string> warnings;
    CHECK_FALSE(apply_config("table = snooker\n", o, warnings));
    CHECK(o.setup.table == TableSize::snooker);
    CHECK_FALSE(parse_game_options({"--table", "12ft"}, why));
    CHECK(why.find("snooker") != std::string::npos);
}
