#include "player/stats_figures.hpp"

#include <cctype>

#include <cmath>

namespace termpool {
namespace {

std::string count(int n) {
    return std::to_string(n);
}

std::string ratio(int a, int b) {
    return count(a) + "/" + count(b);
}

std::string over(const char* a, int va, const char* b, int vb) {
    return std::string("more ") + a + " (" + count(va) + ") than " + b + " (" + count(vb) + ")";
}

// What no game of either kind could give; `games` names the racks or frames.
std::optional<std::string> shared_contradiction(const PlayerStats& s, const std::string& games) {
    if (s.racks_won > s.racks_played)
        return over((games + " won").c_str(), s.racks_won, (games + " played").c_str(),
                    s.racks_played);
    if (s.pot_attempts > s.shots)
        return over("pot attempts", s.pot_attempts, "shots", s.shots);
    if (s.pots_made > s.pot_attempts)
        return over("pots made", s.pots_made, "pot attempts", s.pot_attempts);
    if (s.fouls > s.shots)
        return over("fouls", s.fouls, "shots", s.shots);
    return std::nullopt;
}

// ---------------------------------------------------------------------------------------------
// Pool: racks, balls, break-and-runs and runs.

constexpr StatsCount pool_counts[] = {
    {"won", "racks won", &PlayerStats::racks_won},
    {"played", "racks played", &PlayerStats::racks_played},
    {"shots", "shots", &PlayerStats::shots},
    {"attempts", "pot attempts", &PlayerStats::pot_attempts},
    {"pots", "pots made", &PlayerStats::pots_made},
    {"potted", "balls potted", &PlayerStats::balls_potted},
    {"fouls", "fouls", &PlayerStats::fouls},
    {"break-and-runs", "break-and-runs", &PlayerStats::break_and_runs},
    {"longest-run", "longest run", &PlayerStats::longest_run},
};

constexpr StatsBoxRow pool_box[] = {
    {"Racks won", [](const BoxFigures& f) { return count(f.stats.racks_won); }},
    {"Balls potted", [](const BoxFigures& f) { return count(f.stats.balls_potted); }},
    {"Pot success", [](const BoxFigures& f) { return pot_success_text(f.stats); }},
    {"Fouls", [](const BoxFigures& f) { return count(f.stats.fouls); }},
    {"Longest run", [](const BoxFigures& f) { return count(f.stats.longest_run); }},
    {"Break-and-runs", [](const BoxFigures& f) { return count(f.stats.break_and_runs); }},
};

constexpr StatsColumn pool_table[] = {
    {"Racks", [](const PlayerStats& s) { return ratio(s.racks_won, s.racks_played); }},
    {"Balls", [](const PlayerStats& s) { return count(s.balls_potted); }},
    {"Pots", [](const PlayerStats& s) { return ratio(s.pots_made, s.pot_attempts); }},
    {"Pot success", pot_success_text},
    {"Fouls", [](const PlayerStats& s) { return count(s.fouls); }},
    {"B&R", [](const PlayerStats& s) { return count(s.break_and_runs); }},
    {"Run", [](const PlayerStats& s) { return count(s.longest_run); }},
};

constexpr const char* pool_legend =
    "Racks: won/played. Balls: object balls potted. Pots: shots that potted\n"
    "a ball and kept the table, of those that tried (breaks, safeties and\n"
    "push-outs do not try). B&R: break-and-runs. Run: most balls in one visit.\n";

std::optional<std::string> pool_contradiction(const PlayerStats& s) {
    if (auto shared = shared_contradiction(s, "racks"))
        return shared;
    if (s.break_and_runs > s.racks_won)
        return over("break-and-runs", s.break_and_runs, "racks won", s.racks_won);
    if (s.longest_run > s.balls_potted)
        return "a longest run (" + count(s.longest_run) + ") longer than all balls potted (" +
               count(s.balls_potted) + ")";
    return std::nullopt;
}

// ---------------------------------------------------------------------------------------------
// Snooker: frames, points and breaks.

constexpr StatsCount snooker_counts[] = {
    {"won", "frames won", &PlayerStats::racks_won},
    {"played", "frames played", &PlayerStats::racks_played},
    {"shots", "shots", &PlayerStats::shots},
    {"attempts", "pot attempts", &PlayerStats::pot_attempts},
    {"pots", "pots made", &PlayerStats::pots_made},
    {"potted", "balls potted", &PlayerStats::balls_potted},
    {"fouls", "fouls", &PlayerStats::fouls},
    {"points", "points", &PlayerStats::points},
    {"highest-break", "highest break", &PlayerStats::highest_break},
    {"centuries", "centuries", &PlayerStats::centuries},
};

constexpr StatsBoxRow snooker_box[] = {
    {"Frames won", [](const BoxFigures& f) { return count(f.stats.racks_won); }},
    {"Frame score", [](const BoxFigures& f) { return count(f.frame_score); }},
    {"Highest break", [](const BoxFigures& f) { return count(f.stats.highest_break); }},
    {"Centuries", [](const BoxFigures& f) { return count(f.stats.centuries); }},
    {"Balls potted", [](const BoxFigures& f) { return count(f.stats.balls_potted); }},
    {"Pot success", [](const BoxFigures& f) { return pot_success_text(f.stats); }},
    {"Fouls", [](const BoxFigures& f) { return count(f.stats.fouls); }},
};

// Points per frame, one decimal; "-" before the first frame.
std::string points_per_frame(const PlayerStats& s) {
    if (s.racks_played <= 0)
        return "-";
    const long tenths = std::lround(10.0 * s.points / s.racks_played);
    return count(static_cast<int>(tenths / 10)) + "." + count(static_cast<int>(tenths % 10));
}

constexpr StatsColumn snooker_table[] = {
    {"Frames", [](const PlayerStats& s) { return ratio(s.racks_won, s.racks_played); }},
    {"Points", [](const PlayerStats& s) { return count(s.points); }},
    {"Per frame", points_per_frame},
    {"High", [](const PlayerStats& s) { return count(s.highest_break); }},
    {"100s", [](const PlayerStats& s) { return count(s.centuries); }},
    {"Pots", [](const PlayerStats& s) { return ratio(s.pots_made, s.pot_attempts); }},
    {"Pot success", pot_success_text},
    {"Fouls", [](const PlayerStats& s) { return count(s.fouls); }},
};

constexpr const char* snooker_legend =
    "Frames: won/played. Points: frame scores added up (the opponent's fouls\n"
    "included). High: highest break. 100s: centuries (breaks of 100 or more).\n"
    "Pots: shots that potted a ball and kept the table, of those that tried\n"
    "(the break-off does not try).\n";

std::optional<std::string> snooker_contradiction(const PlayerStats& s) {
    if (auto shared = shared_contradiction(s, "frames"))
        return shared;
    if (s.highest_break > s.points)
        return "a highest break (" + count(s.highest_break) + ") above all points (" +
               count(s.points) + ")";
    // Every century is a break of 100 or more: they cannot outnumber a hundredth of the points,
    // and the highest break is one of them.
    if (s.centuries > s.points / 100)
        return count(s.centuries) + " centuries in " + count(s.points) + " points";
    if ((s.centuries > 0) != (s.highest_break >= 100))
        return count(s.centuries) + " centuries with a highest break of " + count(s.highest_break);
    return std::nullopt;
}

const StatsFigures pool_figures{pool_counts, pool_box, pool_table, pool_legend, pool_contradiction};
const StatsFigures snooker_figures{snooker_counts, snooker_box, snooker_table, snooker_legend,
                                   snooker_contradiction};

} // namespace

StatsKind stats_kind_of(StatsGame game) {
    return game ? stats_kind(*game) : StatsKind::pool;
}

std::string stats_game_key(StatsGame game) {
    return game ? game_type_name(*game) : "mixed";
}

bool parse_stats_game_key(std::string_view key, StatsGame& game) {
    if (key == "mixed") {
        game.reset();
        return true;
    }
    // The name the registry writes, not another spelling: the file is written by the program.
    const GameRow* row = game_registry().find(key);
    if (row == nullptr || key != row->name)
        return false;
    game = row->type;
    return true;
}

std::vector<GameType> stats_game_order() {
    std::vector<GameType> order;
    for (const GameRow& row : game_registry().rows())
        order.push_back(row.type);
    return order;
}

std::string stats_game_title(StatsGame game) {
    if (!game)
        return "All games before statistics were kept per game (racks and frames together)";
    // The registry's title, as a heading: "Snooker".
    std::string title = game_row(*game).title;
    if (!title.empty())
        title[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(title[0])));
    return title;
}

const StatsFigures& stats_figures(StatsKind kind) {
    return kind == StatsKind::snooker ? snooker_figures : pool_figures;
}

std::string pot_success_text(const PlayerStats& s) {
    const auto success = pot_success(s);
    if (!success)
        return "-";
    return std::to_string(static_cast<int>(std::lround(*success * 100))) + "%";
}

} // namespace termpool
