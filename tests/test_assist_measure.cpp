// How much of a game Space alone plays under each assist, against the hard computer: hidden
// (it plays 40 games), run with `build/termpool_tests '[.assist-measure]'`. It prints the balls
// the Space presser pocketed in each seeded game under guided and under standard.
#include <catch2/catch.hpp>
#include <cstdio>

#include "assist_play.hpp"

using termpool::Assist;
using termpool::GameType;
using termpool::Level;
using termpool::test::space_only_game;
using termpool::test::SpaceOnlyGame;

TEST_CASE("Space alone against hard: balls pocketed under guided and standard",
          "[.assist-measure]") {
    int totals[2] = {0, 0}, breaks[2] = {0, 0};
    std::printf("seed  guided (break, shots, fouls, won)  standard (break, shots, fouls, won)\n");
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const SpaceOnlyGame guided =
            space_only_game(GameType::eight_ball, seed, Assist::guided, Level::hard);
        const SpaceOnlyGame standard =
            space_only_game(GameType::eight_ball, seed, Assist::standard, Level::hard);
        totals[0] += guided.potted;
        totals[1] += standard.potted;
        breaks[0] += guided.on_break;
        breaks[1] += standard.on_break;
        std::printf("%4llu  %6d (%d, %d, %d, %s)  %8d (%d, %d, %d, %s)\n",
                    static_cast<unsigned long long>(seed), guided.potted, guided.on_break,
                    guided.shots, guided.fouls, guided.winner == 1 ? "yes" : "no", standard.potted,
                    standard.on_break, standard.shots, standard.fouls,
                    standard.winner == 1 ? "yes" : "no");
        std::fflush(stdout);
    }
    std::printf("total %6d (%d on the break)  %8d (%d on the break)\n", totals[0], breaks[0],
                totals[1], breaks[1]);
    CHECK(totals[1] < totals[0]);
}
