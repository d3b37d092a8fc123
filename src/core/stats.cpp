// Player statistics: the tally of a game's shots (definitions in termpool/stats.hpp).
#include <termpool/game_registry.hpp>
#include <termpool/match.hpp>
#include <termpool/stats.hpp>

#include <algorithm>
#include <limits>

namespace termpool {
namespace {

// Object balls that count as potted for a legal shot: those that stay down.
int balls_kept_down(const Verdict& v) {
    // An 8 on an 8-ball break that does not win owes the breaker a choice: spot it or
    // re-break. Either way it does not stay down.
    const bool eight_comes_back = std::ranges::count(v.choices, Choice::spot_eight) > 0;
    int n = 0;
    for (const int id : v.pocketed)
        if (id != 0 && std::ranges::count(v.respotted, id) == 0 && !(eight_comes_back && id == 8))
            ++n;
    return n;
}

// Object balls potted by a legal shot, as `kind` counts them.
int balls_potted(StatsKind kind, const Verdict& v) {
    if (kind == StatsKind::pool)
        return balls_kept_down(v);
    // Snooker: colours potted while reds remain come back, but they were potted and scored.
    return static_cast<int>(std::ranges::count_if(v.pocketed, [](int id) { return id != 0; }));
}

} // namespace

void PlayerStats::add(const PlayerStats& more) {
    // Totals read from a file may be as large as an int holds: they stop there rather than
    // wrap (and an upper bound kept by each count, like pots made <= attempts, still holds).
    auto sum = [](int& total, int more_of) {
        const long long s = static_cast<long long>(total) + std::max(more_of, 0);
        total = static_cast<int>(std::min<long long>(s, std::numeric_limits<int>::max()));
    };
    sum(racks_won, more.racks_won);
    sum(racks_played, more.racks_played);
    sum(shots, more.shots);
    sum(pot_attempts, more.pot_attempts);
    sum(pots_made, more.pots_made);
    sum(balls_potted, more.balls_potted);
    sum(fouls, more.fouls);
    sum(break_and_runs, more.break_and_runs);
    longest_run = std::max(longest_run, more.longest_run);
    sum(points, more.points);
    highest_break = std::max(highest_break, more.highest_break);
    sum(centuries, more.centuries);
}

std::optional<double> pot_success(const PlayerStats& stats) {
    if (stats.pot_attempts <= 0)
        return std::nullopt;
    return static_cast<double>(stats.pots_made) / stats.pot_attempts;
}

StatsKind stats_kind(GameType type) {
    return game_row(type).stats;
}

void StatsTally::on_shot(int shooter, bool was_break, const ShotCall& call, const Verdict& v) {
    if (shooter != 1 && shooter != 2)
        return;
    if (rack_over_) {
        rack_over_ = false;
        frame_score_ = {0, 0};
    }
    if (was_break || visitor_ != shooter) {
        visitor_ = shooter;
        run_ = 0;
        run_from_break_ = was_break;
    }
    PlayerStats& me = stats_[shooter - 1];
    const int other = 3 - shooter;
    const bool foul = v.foul != Foul::none;
    // A snooker frame may end on a legal pot that still loses it on points: the pot and its
    // points are the shooter's all the same.
    const bool frame_ends_on_pot = kind_ == StatsKind::snooker && v.winner != 0 && !foul;
    const bool legal = !foul && (v.winner != other || frame_ends_on_pot);
    const int potted = legal ? balls_potted(kind_, v) : 0;
    const bool keeps_table = v.winner == shooter || (frame_ends_on_pot && v.points > 0) ||
                             (v.winner == 0 && v.next_shooter == shooter);

    ++me.shots;
    if (foul)
        ++me.fouls;
    me.balls_potted += potted;
    if (!was_break && !call.call.safety && !call.push_out) {
        ++me.pot_attempts;
        if (legal && potted > 0 && keeps_table)
            ++me.pots_made;
    }
    bool visit_over = foul || v.winner != 0 || !keeps_table;
    switch (kind_) {
    case StatsKind::pool:
        run_ += potted;
        me.longest_run = std::max(me.longest_run, run_);
        if (v.winner == shooter && run_from_break_)
            ++me.break_and_runs;
        break;
    case StatsKind::snooker:
        me.points += v.points;
        stats_[other - 1].points += v.penalty;
        frame_score_[shooter - 1] += v.points;
        frame_score_[other - 1] += v.penalty;
        if (legal && v.points > 0) {
            const int before = run_;
            run_ += v.points;
            me.highest_break = std::max(me.highest_break, run_);
            if (before < 100 && run_ >= 100)
                ++me.centuries;
        }
        // A re-spotted black (the scores level at the end) is played from the D by whoever the
        // lots name: a new visit, even for the player who potted the black.
        visit_over =
            visit_over || v.points == 0 || (v.winner == 0 && v.ball_in_hand != BallInHand::none);
        break;
    }
    end_rack(v.winner);
    if (visit_over)
        visitor_ = 0;
}

void StatsTally::end_rack(int winner) {
    if (winner != 1 && winner != 2)
        return;
    ++stats_[0].racks_played;
    ++stats_[1].racks_played;
    ++stats_[winner - 1].racks_won;
    visitor_ = 0;
    rack_over_ = true;
}

void StatsTally::on_conceded(int winner) {
    end_rack(winner);
}

std::variant<StatsTally, RecordError> tally_record(const GameRecord& record) {
    const auto replayed = Match::replay(record);
    if (const RecordError* problem = std::get_if<RecordError>(&replayed))
        return *problem;
    return std::get<Match>(replayed).tally();
}

std::variant<std::array<PlayerStats, 2>, RecordError> stats_of_record(const GameRecord& record) {
    const auto tally = tally_record(record);
    if (const RecordError* problem = std::get_if<RecordError>(&tally))
        return *problem;
    return std::get<StatsTally>(tally).both();
}

} // namespace termpool
