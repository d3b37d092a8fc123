#include <catch2/catch.hpp>
#include <termpool/snooker_layout.hpp>

using namespace termpool;

TEST_CASE("snooker values: red 1, yellow 2 to black 7, the cue ball nothing", "[snooker]") {
    CHECK(snooker_value(0) == 0);
    for (int id = snooker_first_red; id <= snooker_last_red; ++id)
        CHECK(snooker_value(id) == 1);
    CHECK(snooker_value(snooker_yellow) == 2);
    CHECK(snooker_value(snooker_brown) == 4);
    CHECK(snooker_value(snooker_black) == 7);
    CHECK(snooker_value(snooker_black + 1) == 0);
}

TEST_CASE("snooker marks on a 12 ft table: baulk line, D and spots", "[snooker]") {
    Table t;
    t.length = snooker_table_length;
    t.width = snooker_table_width;
    CHECK(snooker_baulk_x(t) == Approx(0.737));
    CHECK(snooker_spot(t, snooker_brown).x == Approx(0.737));
    CHECK(snooker_spot(t, snooker_yellow).y == Approx(0.889 - 0.292));
    CHECK(snooker_spot(t, snooker_green).y == Approx(0.889 + 0.292));
    CHECK(snooker_spot(t, snooker_blue).x == Approx(3.569 / 2));
    CHECK(snooker_spot(t, snooker_pink).x == Approx(3.569 * 0.75));
    CHECK(snooker_spot(t, snooker_black).x == Approx(3.569 - 0.324));
    CHECK(in_snooker_d(t, snooker_spot(t, snooker_yellow)));
    CHECK(in_snooker_d(t, {0.5, 0.889}));
    CHECK_FALSE(in_snooker_d(t, {0.8, 0.889}));       // beyond the baulk line
    CHECK_FALSE(in_snooker_d(t, {0.5, 0.889 + 0.3})); // outside the semicircle
}
