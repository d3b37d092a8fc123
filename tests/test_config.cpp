// The config file: defaults for the game, with bad values refused at their line.
#include <catch2/catch.hpp>

#include "tui/config.hpp"

using namespace termpool;
using namespace termpool::tui;

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
    CHECK(o.game == GameType::nine_ball);
    CHECK(o.table == TableSize::seven_foot);
    CHECK(o.timed_power);
    CHECK_FALSE(o.aim_aid);
    CHECK(o.default_level == Level::pro);
    // The command line still wins, and --vs-computer without a level takes the config's.
    std::string why;
    const auto parsed = parse_game_options({"--game", "8ball", "--vs-computer"}, why, o);
    REQUIRE(parsed);
    CHECK(parsed->game == GameType::eight_ball);
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
        {"game = snooker\n", "1: unknown game 'snooker'"},
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
