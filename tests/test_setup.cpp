// The game's setup and the one text form of the cloth model.
#include <catch2/catch.hpp>
#include <string>
#include <string_view>
#include <termpool/record.hpp>
#include <termpool/setup.hpp>
#include <vector>

#include "player/options.hpp"

using namespace termpool;

namespace {

std::variant<FrictionModel, FrictionProblem> parsed(std::vector<std::string_view> words) {
    return parse_friction(words);
}

FrictionProblem problem_of(std::vector<std::string_view> words) {
    const auto result = parsed(std::move(words));
    REQUIRE(std::holds_alternative<FrictionProblem>(result));
    return std::get<FrictionProblem>(result);
}

} // namespace

TEST_CASE("every cloth model reads back from the words it is written as", "[setup]") {
    FrictionModel decay{FrictionKind::decay, 0.556, 0};
    FrictionModel constant{FrictionKind::constant, 0, 0.545};
    FrictionModel combined{FrictionKind::combined, 0.1 + 0.2, 1e-3};
    for (const FrictionModel& model : {FrictionModel{}, decay, constant, combined}) {
        const std::string text = format_friction(model);
        std::vector<std::string_view> words;
        for (std::size_t at = 0; at < text.size();) {
            const std::size_t end = std::min(text.find(' ', at), text.size());
            words.push_back(std::string_view(text).substr(at, end - at));
            at = end + 1;
        }
        const auto back = parse_friction(words);
        REQUIRE(std::holds_alternative<FrictionModel>(back));
        const FrictionModel& read = std::get<FrictionModel>(back);
        CHECK(read.kind == model.kind);
        CHECK(read.decay_rate == model.decay_rate); // bit for bit: 0.1 + 0.2 is not 0.3
        CHECK(read.deceleration == model.deceleration);
    }
    CHECK(format_friction(combined) == "combined 0.30000000000000004 0.001");
    CHECK(format_friction(FrictionModel{}) == "physical");
}

TEST_CASE("bad cloth-model words say what is wrong and where", "[setup]") {
    using Kind = FrictionProblem::Kind;
    CHECK(problem_of({}).kind == Kind::unknown_model);
    CHECK(problem_of({"sticky"}).kind == Kind::unknown_model);
    CHECK(problem_of({"decay"}).kind == Kind::missing_constant);
    CHECK(problem_of({"combined", "0.5"}).word == 2);
    CHECK(problem_of({"physical", "1"}).kind == Kind::extra_word);
    CHECK(problem_of({"decay", "0.5", "1"}).word == 2);
    CHECK(problem_of({"decay", "fast"}).kind == Kind::not_a_number);
    CHECK(problem_of({"decay", "0,5"}).kind == Kind::not_a_number); // no locale's decimal comma
    CHECK(problem_of({"constant", "inf"}).kind == Kind::not_finite);
    CHECK(problem_of({"constant", "1e999"}).kind == Kind::not_finite);
    CHECK(problem_of({"constant", "0"}).kind == Kind::not_positive);
    CHECK(problem_of({"combined", "0.5", "-1"}).kind == Kind::not_positive);
    CHECK(problem_of({"combined", "0.5", "-1"}).word == 2);
    CHECK(std::holds_alternative<FrictionModel>(parsed({"decay", "+0.5"})));
}

TEST_CASE("--game takes 10-ball by any of its names", "[setup][ten]") {
    for (const char* name : {"10ball", "ten-ball", "10-ball"}) {
        std::string error;
        const auto o = termpool::parse_game_options({"--game", name}, error);
        REQUIRE(o);
        CHECK(o->setup.game == GameType::ten_ball);
    }
    std::string error;
    CHECK_FALSE(termpool::parse_game_options({"--game", "11ball"}, error));
    CHECK(error.find("10ball") != std::string::npos);
}

TEST_CASE("the game's options carry the setup, with their own wording for bad models", "[setup]") {
    std::string error;
    const auto o = termpool::parse_game_options({"--game", "9ball", "--table", "7ft", "--friction",
                                                 "combined", "0.5", "0.25", "--seed", "3"},
                                                error);
    REQUIRE(o);
    CHECK(o->setup.game == GameType::nine_ball);
    CHECK(o->setup.table == TableSize::seven_foot);
    CHECK(o->setup.physics.friction.kind == FrictionKind::combined);
    CHECK(o->setup.physics.friction.deceleration == 0.25);
    CHECK(o->seed == 3u);
    CHECK(make_table(o->setup).size == TableSize::seven_foot);

    CHECK_FALSE(termpool::parse_game_options({"--friction", "combined", "0.5"}, error));
    CHECK(error == "--friction combined needs A");
    CHECK_FALSE(termpool::parse_game_options({"--friction", "combined", "x"}, error));
    CHECK(error == "K must be a positive number"); // the K given is read before A is asked for
    CHECK_FALSE(termpool::parse_game_options({"--friction", "decay", "x"}, error));
    CHECK(error == "K must be a positive number");
    CHECK_FALSE(termpool::parse_game_options({"--friction", "slow"}, error));
    CHECK(error == "unknown friction model 'slow' (physical, decay K, constant A or combined K A)");
}

TEST_CASE("--cue sets the shaft's end mass", "[setup][cue]") {
    std::string error;
    CHECK(termpool::parse_game_options({}, error)->setup.physics.cue_end_mass ==
          standard_shaft_end_mass);
    CHECK(termpool::parse_game_options({"--cue", "low-deflection"}, error)
              ->setup.physics.cue_end_mass == low_deflection_end_mass);
    CHECK(termpool::parse_game_options({"--cue", "none"}, error)->setup.physics.cue_end_mass == 0);
    CHECK(termpool::parse_game_options({"--cue", "standard"}, error)->setup.physics.cue_end_mass ==
          standard_shaft_end_mass);
    CHECK_FALSE(termpool::parse_game_options({"--cue", "ash"}, error));
    CHECK(error == "--cue takes standard, low-deflection or none");
    CHECK_FALSE(termpool::parse_game_options({"--cue"}, error));
    CHECK(error == "--cue needs a value");
}

TEST_CASE("a save's friction and name lines keep the save's own wording", "[setup][record]") {
    const auto problem = [](const std::string& line) -> std::string {
        const auto parsed = parse_record("termpool-record 1\ngame 8ball\n" + line + "\nend\n");
        const auto* e = std::get_if<RecordError>(&parsed);
        return e ? std::to_string(e->line) + ": " + e->message : "";
    };
    CHECK(problem("friction combined 0.5 0.25").empty());
    CHECK(problem("friction decay 0") == "3: friction constants must be positive numbers");
    CHECK(problem("friction decay +0.5") == "3: friction constants must be positive numbers");
    CHECK(problem("friction combined 0.5 +0.3") ==
          "3: friction constants must be positive numbers");
    CHECK(problem("friction bogus x") == "3: friction constants must be positive numbers");
    CHECK(problem("friction decay 1 2") == "3: bad friction line");
    CHECK(problem("friction physical 1") == "3: bad friction line");
    CHECK(problem("friction decay") == "3: unknown or malformed line 'friction'");
    CHECK(problem("player1 Ann Lee  ").empty()); // spaces at the end are dropped
    CHECK(problem("player2 A\x1b[2JB").starts_with("3: a player's name must be text"));
}
