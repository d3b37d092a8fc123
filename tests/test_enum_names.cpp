// The name tables (include/termpool/enum_names.hpp): every table reads back what it writes,
// every spelling the hand-made switches and parsers wrote or read before the tables still
// does, and any other word is refused.

#include <algorithm>
#include <catch2/catch.hpp>
#include <cctype>
#include <string>
#include <termpool/assist.hpp>
#include <termpool/ball.hpp>
#include <termpool/enum_names.hpp>
#include <termpool/event.hpp>
#include <termpool/level.hpp>
#include <termpool/params.hpp>
#include <termpool/race.hpp>
#include <termpool/rack.hpp>
#include <termpool/record.hpp>
#include <termpool/rules_names.hpp>
#include <termpool/setup.hpp>
#include <termpool/table.hpp>
#include <utility>
#include <vector>

#include "cli/scenario.hpp"
#include "hall/protocol.hpp"
#include "tui/grid_dump.hpp"

using namespace termpool;

namespace {

std::string upper(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return text;
}

// Every row of `table` writes its name and reads back from each of its spellings; no spelling
// is two rows'; a word of no row, the empty word and a name in capitals are refused.
template <class T, std::size_t N> void check_round_trip(const NameRow<T> (&table)[N]) {
    std::vector<std::string> spellings;
    for (const NameRow<T>& row : table) {
        INFO("name " << row.name);
        CHECK(std::string(name_of(table, row.value)) == row.name);
        CHECK(parse_name(table, row.name) == row.value);
        spellings.push_back(row.name);
        for (const char* other : row.also) {
            if (!other)
                continue;
            CHECK(parse_name(table, other) == row.value);
            spellings.emplace_back(other);
        }
        if (upper(row.name) != row.name)
            CHECK_FALSE(parse_name(table, upper(row.name)));
        CHECK_FALSE(parse_name(table, std::string(row.name) + " "));
    }
    std::sort(spellings.begin(), spellings.end());
    CHECK(std::adjacent_find(spellings.begin(), spellings.end()) == spellings.end());
    CHECK_FALSE(parse_name(table, "no-such-word"));
    CHECK_FALSE(parse_name(table, ""));
}

// The names the hand-made switches wrote, checked against the table's writer and reader.
template <class T, std::size_t N>
void check_old_names(const NameRow<T> (&table)[N],
                     std::initializer_list<std::pair<T, const char*>> old) {
    CHECK(old.size() == N); // one name a value, as each switch had
    for (const auto& [value, name] : old) {
        INFO("old name " << name);
        CHECK(std::string(name_of(table, value)) == name);
        CHECK(parse_name(table, name) == value);
    }
}

enum class Fruit { apple, pear, quince };

constexpr NameRow<Fruit> fruit_names[] = {
    {Fruit::apple, "apple", {"malus"}},
    {Fruit::pear, "pear"},
    {Fruit::quince, "quince", {"coing", "membrillo"}},
};
static_assert(names_in_order(fruit_names));
static_assert(parse_name(fruit_names, "membrillo") == Fruit::quince); // usable at compile time
static_assert(std::string_view(name_of(fruit_names, Fruit::pear)) == "pear");

constexpr NameRow<Fruit> shuffled_names[] = {{Fruit::pear, "pear"}, {Fruit::apple, "apple"}};
static_assert(!names_in_order(shuffled_names));

} // namespace

TEST_CASE("a name table writes the name and reads every spelling", "[names]") {
    check_round_trip(fruit_names);
    CHECK(parse_name(fruit_names, "malus") == Fruit::apple);
    CHECK(parse_name(fruit_names, "coing") == Fruit::quince);
    CHECK(std::string(name_of(fruit_names, Fruit::quince)) == "quince"); // never the others
    CHECK_FALSE(parse_name(fruit_names, "Apple"));
    CHECK(std::string(name_of(fruit_names, static_cast<Fruit>(7))) == "?");
    CHECK(std::string(name_of(fruit_names, static_cast<Fruit>(7), "apple")) == "apple");
}

TEST_CASE("every name table reads back what it writes", "[names]") {
    check_round_trip(level_names);
    check_round_trip(assist_names);
    check_round_trip(break_rule_names);
    check_round_trip(table_size_names);
    check_round_trip(motion_state_names);
    check_round_trip(event_kind_names);
    check_round_trip(group_names);
    check_round_trip(player1_group_names);
    check_round_trip(ball_in_hand_names);
    check_round_trip(foul_names);
    check_round_trip(choice_names);
    check_round_trip(win_reason_names);
    check_round_trip(ball_on_names);
    check_round_trip(collision_model_names);
    check_round_trip(cushion_model_names);
    check_round_trip(ball_friction_model_names);
    check_round_trip(friction_kind_names);
    check_round_trip(rack_type_names);
    check_round_trip(cue_names);
    check_round_trip(hall::error_code_names);
    check_round_trip(hall::seat_kind_names);
    check_round_trip(hall::table_state_names);
}

TEST_CASE("the names the old switches wrote are the tables' names", "[names]") {
    check_old_names(level_names, {{Level::easy, "easy"},
                                  {Level::medium, "medium"},
                                  {Level::hard, "hard"},
                                  {Level::pro, "pro"}});
    check_old_names(
        assist_names,
        {{Assist::guided, "guided"}, {Assist::standard, "standard"}, {Assist::pro, "pro"}});
    check_old_names(break_rule_names,
                    {{BreakRule::alternate, "alternate"}, {BreakRule::winner, "winner"}});
    check_old_names(table_size_names, {{TableSize::seven_foot, "7ft"},
                                       {TableSize::eight_foot, "8ft"},
                                       {TableSize::nine_foot, "9ft"},
                                       {TableSize::snooker, "snooker"}});
    check_old_names(motion_state_names, {{MotionState::stationary, "stationary"},
                                         {MotionState::spinning, "spinning"},
                                         {MotionState::sliding, "sliding"},
                                         {MotionState::rolling, "rolling"},
                                         {MotionState::pocketed, "pocketed"}});
    check_old_names(event_kind_names, {{EventKind::ball_ball, "ball-ball"},
                                       {EventKind::cushion, "cushion"},
                                       {EventKind::jaw, "jaw"},
                                       {EventKind::pocket, "pocket"},
                                       {EventKind::sliding, "sliding"},
                                       {EventKind::rolling, "rolling"},
                                       {EventKind::spinning, "spinning"},
                                       {EventKind::stopped, "stopped"},
                                       {EventKind::off_table, "off-table"}});
    check_old_names(
        group_names,
        {{Group::open, "open"}, {Group::solids, "solids"}, {Group::stripes, "stripes"}});
    check_old_names(
        player1_group_names,
        {{Group::open, "open"}, {Group::solids, "1=solids"}, {Group::stripes, "1=stripes"}});
    check_old_names(ball_in_hand_names, {{BallInHand::none, "none"},
                                         {BallInHand::kitchen, "kitchen"},
                                         {BallInHand::anywhere, "anywhere"},
                                         {BallInHand::d, "d"}});
    check_old_names(foul_names, {{Foul::none, "none"},
                                 {Foul::scratch, "scratch"},
                                 {Foul::cue_off_table, "cue-off-table"},
                                 {Foul::off_table, "off-table"},
                                 {Foul::no_contact, "no-contact"},
                                 {Foul::wrong_ball_first, "wrong-ball-first"},
                                 {Foul::no_rail, "no-rail"},
                                 {Foul::bad_break, "bad-break"},
                                 {Foul::pot_not_on, "pot-not-on"},
                                 {Foul::free_ball_snooker, "free-ball-snooker"}});
    check_old_names(choice_names, {{Choice::play_on, "play-on"},
                                   {Choice::re_rack, "re-rack"},
                                   {Choice::re_break, "re-break"},
                                   {Choice::spot_eight, "spot-eight"},
                                   {Choice::take_solids, "take-solids"},
                                   {Choice::take_stripes, "take-stripes"},
                                   {Choice::shoot, "shoot"},
                                   {Choice::pass_back, "pass-back"},
                                   {Choice::offender_plays, "offender-plays"},
                                   {Choice::replace_and_replay, "replace-and-replay"},
                                   {Choice::concede, "concede"}});
    check_old_names(win_reason_names, {{WinReason::none, "none"},
                                       {WinReason::eight_pocketed, "eight-pocketed"},
                                       {WinReason::eight_on_break, "eight-on-break"},
                                       {WinReason::eight_early, "eight-early"},
                                       {WinReason::eight_on_foul, "eight-on-foul"},
                                       {WinReason::eight_wrong_pocket, "eight-wrong-pocket"},
                                       {WinReason::eight_off_table, "eight-off-table"},
                                       {WinReason::nine_pocketed, "nine-pocketed"},
                                       {WinReason::three_fouls, "three-fouls"},
                                       {WinReason::ten_pocketed, "ten-pocketed"},
                                       {WinReason::frame_won, "frame-won"},
                                       {WinReason::conceded, "conceded"},
                                       {WinReason::three_misses, "three-misses"}});
    check_old_names(
        ball_on_names,
        {{BallOn::red, "red"}, {BallOn::colour, "colour"}, {BallOn::in_order, "in-order"}});
    check_old_names(collision_model_names,
                    {{CollisionModel::physical, "physical"}, {CollisionModel::ideal, "ideal"}});
    check_old_names(cushion_model_names, {{CushionModel::physical, "physical"},
                                          {CushionModel::ideal, "ideal"},
                                          {CushionModel::mirror, "mirror"},
                                          {CushionModel::stronge, "stronge"}});
    check_old_names(ball_friction_model_names,
                    {{BallFrictionModel::fit, "fit"}, {BallFrictionModel::constant, "constant"}});
    check_old_names(friction_kind_names, {{FrictionKind::physical, "physical"},
                                          {FrictionKind::decay, "decay"},
                                          {FrictionKind::constant, "constant"},
                                          {FrictionKind::combined, "combined"}});
    check_old_names(rack_type_names, {{RackType::eight_ball, "8ball"},
                                      {RackType::nine_ball, "9ball"},
                                      {RackType::ten_ball, "10ball"},
                                      {RackType::snooker, "snooker"}});
    check_old_names(cue_names, {{standard_shaft_end_mass, "standard"},
                                {low_deflection_end_mass, "low-deflection"},
                                {0.0, "none"}});
    check_old_names(hall::error_code_names, {{hall::ErrorCode::syntax, "syntax"},
                                             {hall::ErrorCode::too_long, "too-long"},
                                             {hall::ErrorCode::version, "version"},
                                             {hall::ErrorCode::rate, "rate"},
                                             {hall::ErrorCode::hello_first, "hello-first"},
                                             {hall::ErrorCode::full, "full"},
                                             {hall::ErrorCode::no_table, "no-table"},
                                             {hall::ErrorCode::seat_taken, "seat-taken"},
                                             {hall::ErrorCode::not_seated, "not-seated"},
                                             {hall::ErrorCode::refused, "refused"},
                                             {hall::ErrorCode::replaced, "replaced"},
                                             {hall::ErrorCode::internal, "internal"},
                                             {hall::ErrorCode::name_taken, "name-taken"}});
    check_old_names(hall::seat_kind_names, {{hall::SeatKind::empty, "empty"},
                                            {hall::SeatKind::player, "player"},
                                            {hall::SeatKind::away, "away"},
                                            {hall::SeatKind::computer, "computer"}});
    check_old_names(hall::table_state_names, {{hall::TableState::waiting, "waiting"},
                                              {hall::TableState::playing, "playing"},
                                              {hall::TableState::over, "over"}});
}

TEST_CASE("the named functions write and read through the tables", "[names]") {
    CHECK(parse_level("pro") == Level::pro);
    CHECK_FALSE(parse_level("Pro"));
    CHECK(std::string(level_name(Level::medium)) == "medium");
    CHECK(parse_assist("guided") == Assist::guided);
    CHECK_FALSE(parse_assist("expert"));
    CHECK(parse_break_rule("winner") == BreakRule::winner);
    CHECK_FALSE(parse_break_rule("loser"));
    CHECK(parse_table_size("8ft") == TableSize::eight_foot);
    CHECK_FALSE(parse_table_size("8 ft"));
    CHECK(std::string(foul_name(Foul::pot_not_on)) == "pot-not-on");
    CHECK(std::string(win_reason_name(WinReason::three_misses)) == "three-misses");
    CHECK(std::string(event_kind_name(EventKind::off_table)) == "off-table");
    CHECK(std::string(motion_state_name(MotionState::rolling)) == "rolling");
    CHECK(parse_friction_kind("combined") == FrictionKind::combined);
    CHECK_FALSE(parse_friction_kind("Combined"));
    // The hall writes a word its clients know even for a value out of range.
    CHECK(std::string(hall::error_code_name(static_cast<hall::ErrorCode>(99))) == "internal");
    CHECK(std::string(hall::seat_kind_name(static_cast<hall::SeatKind>(99))) == "empty");
    CHECK(std::string(hall::table_state_name(static_cast<hall::TableState>(99))) == "waiting");
    CHECK(hall::parse_error_code("seat-taken") == hall::ErrorCode::seat_taken);
    CHECK_FALSE(hall::parse_error_code("seat_taken"));
    CHECK(std::string(tui::colour_name(tui::Colour::normal)) == "normal");
    CHECK(std::string(tui::colour_name(tui::Colour::highlight)) == "highlight");
}

TEST_CASE("a record's choose line reads every choice's name", "[names][record]") {
    for (const NameRow<Choice>& row : choice_names) {
        const auto action = parse_action(std::string("choose ") + row.name);
        REQUIRE(std::holds_alternative<RecordedAction>(action));
        CHECK(std::get<RecordedAction>(action).choice == row.value);
        CHECK(format_action(std::get<RecordedAction>(action)) == std::string("choose ") + row.name);
    }
    CHECK(std::holds_alternative<RecordError>(parse_action("choose Play-On")));
    CHECK(std::holds_alternative<RecordError>(parse_action("choose surrender")));
}

TEST_CASE("a scenario reads racks and throw models by name", "[names][scenario]") {
    const auto balls_of = [](const std::string& text) -> std::size_t {
        const auto result = cli::parse_scenario(text);
        REQUIRE(std::holds_alternative<cli::Scenario>(result));
        return std::get<cli::Scenario>(result).balls.size();
    };
    CHECK(balls_of("rack 8ball\n") == 16);
    CHECK(balls_of("rack 9ball\n") == 10);
    CHECK(balls_of("rack 10ball\n") == 11);
    const auto error_of = [](const std::string& text) {
        const auto result = cli::parse_scenario(text);
        REQUIRE(std::holds_alternative<cli::ScenarioError>(result));
        return std::get<cli::ScenarioError>(result).message;
    };
    CHECK(error_of("rack 7ball\n") ==
          "unknown rack '7ball' (expected 8ball, 9ball, 10ball or snooker)");
    CHECK(error_of("throw linear\n") == "unknown throw model 'linear' (expected fit or constant)");
    CHECK(error_of("collision Ideal\n") ==
          "unknown collision model 'Ideal' (expected physical or ideal)");
    const auto thrown = cli::parse_scenario("throw constant 0.07\n");
    REQUIRE(std::holds_alternative<cli::Scenario>(thrown));
    const BallFriction& friction = std::get<cli::Scenario>(thrown).setup.physics.ball_friction;
    CHECK(friction.model == BallFrictionModel::constant);
    CHECK(friction.constant == 0.07);
}
