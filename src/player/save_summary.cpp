#include "player/save_summary.hpp"

#include <algorithm>
#include <termpool/game_registry.hpp>

#include "files/self_command.hpp"

namespace termpool {
namespace {

// "1 minute", "5 minutes".
std::string count_of(long long n, const char* unit) {
    return std::to_string(n) + " " + unit + (n == 1 ? "" : "s");
}

// "1-0": the two players' figures.
std::string pair_of(int first, int second) {
    return std::to_string(first) + "-" + std::to_string(second);
}

} // namespace

std::string age_words(std::time_t written, std::time_t now) {
    const long long seconds = static_cast<long long>(now) - static_cast<long long>(written);
    constexpr long long minute = 60, hour = 60 * minute, day = 24 * hour;
    if (seconds < minute)
        return "just now";
    if (seconds < hour)
        return count_of(seconds / minute, "minute") + " ago";
    if (seconds < day)
        return count_of(seconds / hour, "hour") + " ago";
    if (seconds < 30 * day)
        return count_of(seconds / day, "day") + " ago";
    char date[16] = "";
    std::tm local{};
    if (localtime_r(&written, &local))
        std::strftime(date, sizeof date, "%Y-%m-%d", &local);
    return std::string("on ") + date;
}

std::string game_summary(const Match& game) {
    const GameRecord& r = game.record();
    const GameRow& row = game_row(r.setup.game);
    const bool points = row.scoring == Scoring::points; // a frame's score, a best of N frames
    std::string text = r.names[0] + " v " + r.names[1] + ", " + game_type_name(r.setup.game);
    if (!(row.table && r.setup.table == *row.table))
        text += std::string(", ") + table_size_name(r.setup.table);
    const MatchState& score = game.score();
    const int winner = score.is_race() ? score.match_winner() : game.game().winner();
    if (winner != 0)
        return text + ", won by " + r.names[winner - 1];
    const auto shots = std::count_if(r.actions.begin(), r.actions.end(), [](const auto& a) {
        return a.kind == RecordedAction::Kind::shot;
    });
    text += ", " + count_of(shots, "shot");
    if (points)
        text += ", score " + pair_of(game.game().score_of(1), game.game().score_of(2));
    if (score.is_race())
        text += (points ? ", best of " + std::to_string(best_of_for_race(score.race_to))
                        : ", race to " + std::to_string(score.race_to)) +
                " at " + pair_of(score.racks_won[0], score.racks_won[1]);
    return text;
}

std::string save_words(const SlotSave& save, std::time_t now) {
    const SaveContents& c = save.contents;
    const std::string what = c.game      ? game_summary(*c.game)
                             : c.problem ? "not a game (line " + std::to_string(c.problem->line) +
                                               ": " + c.problem->message + ")"
                                         : "cannot be read";
    return what + ", saved " + age_words(save.written.tv_sec, now) +
           (save.in_use() ? ", being played in another terminal" : "");
}

std::string save_line(const SlotSave& save, std::time_t now) {
    std::string number = std::to_string(save.slot);
    number.insert(0, number.size() < 3 ? 3 - number.size() : 0, ' ');
    return number + "  " + save_words(save, now);
}

std::string removal_words(Removal removal, int slot, const std::string& error) {
    const std::string save = "save " + std::to_string(slot);
    switch (removal) {
    case Removal::removed:
        return "";
    case Removal::missing:
        return "there is no " + save;
    case Removal::finished:
        return save + " is a finished game, kept for " + self_command() +
               " replay: only unfinished saves are listed and removed";
    case Removal::not_a_game:
        return save + " is not a game that can be continued: it is not removed";
    case Removal::in_use:
        return save + " is being played in another terminal: it is not removed";
    case Removal::changed:
        return save + " changed while it was being checked: it is not removed";
    case Removal::failed:
        return error;
    }
    return error;
}

} // namespace termpool
