// What a shot's events tell the referees: its first contact, the balls that went to a rail, the
// balls that dropped and left the table.
#include <catch2/catch.hpp>
#include <termpool/shot_facts.hpp>

using namespace termpool;

namespace {

Event contact(double time, int a, int b) {
    return {time, EventKind::ball_ball, std::min(a, b), std::max(a, b)};
}
Event cushion(double time, int ball) {
    return {time, EventKind::cushion, ball, 2};
}
Event jaw(double time, int ball) {
    return {time, EventKind::jaw, ball, 3};
}

} // namespace

TEST_CASE("shot facts: the first contact, the ones at the same instant, a rail after it",
          "[core][rules]") {
    const ShotFacts none = ShotFacts::from({cushion(0.1, 0)});
    CHECK(none.first_contact == -1);
    CHECK(none.first_contacts.empty());
    CHECK_FALSE(none.rail_after_contact); // a rail before any contact does not count

    const ShotFacts f =
        ShotFacts::from({cushion(0.05, 0), contact(0.2, 0, 5), contact(0.2 + 5e-10, 0, 3),
                         contact(0.3, 0, 7), contact(0.35, 3, 5), cushion(0.4, 5)});
    CHECK(f.first_contact == 5);
    CHECK(f.first_contacts == std::vector<int>{5, 3}); // within a nanosecond; 7 came later
    CHECK(f.rail_after_contact);
}

TEST_CASE("shot facts: each object ball that met a cushion or jaw counts once, whatever its id",
          "[core][rules]") {
    // The cue ball does not count; ball 5 twice and by a jaw, 63 (the last id of the bits), 64
    // and 1000 (in the list), 1000 twice, and a negative id (a layout of the caller's).
    const ShotFacts f = ShotFacts::from({cushion(0.1, 0), cushion(0.2, 5), jaw(0.3, 5),
                                         cushion(0.4, 63), cushion(0.5, 64), jaw(0.6, 1000),
                                         cushion(0.7, 1000), cushion(0.8, -2), cushion(0.9, 1)});
    CHECK(f.balls_to_rail == 6); // 5, 63, 64, 1000, -2, 1
    CHECK(ShotFacts::from({cushion(0.1, 0), cushion(0.2, 0)}).balls_to_rail == 0);
    CHECK(ShotFacts::from({}).balls_to_rail == 0);
}

TEST_CASE("shot facts: the balls that dropped, with their pockets, and those off the table",
          "[core][rules]") {
    const ShotFacts f = ShotFacts::from({contact(0.1, 0, 9),
                                         {0.5, EventKind::pocket, 9, 4},
                                         {0.7, EventKind::pocket, 0, 2},
                                         {0.8, EventKind::off_table, 4, 0}});
    CHECK(f.pocketed == std::vector<int>{9, 0});
    CHECK(f.pockets == std::vector<int>{4, 2});
    CHECK(f.pocket_of(9) == 4);
    CHECK(f.pocket_of(4) == 0);
    CHECK(f.dropped(0));
    CHECK(f.object_ball_dropped());
    CHECK(f.left_table(4));
    CHECK_FALSE(f.left_table(9));
}
