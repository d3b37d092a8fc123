// The rack's log, replayed from the record: the match judges each shot again as it was.

#include "tui/rack_log.hpp"

#include <algorithm>
#include <termpool/game_registry.hpp>
#include <termpool/match.hpp>

#include "tui/help_text.hpp"
#include "tui/messages.hpp"
#include "tui/pocket_cells.hpp"

namespace termpool::tui {
namespace {

std::string ball_words(int id, GameType game) {
    return game_row(game).balls == BallSet::snooker ? snooker_ball_name(id) : std::to_string(id);
}

// What the shooter declared: a safety, a push-out, or the ball and pocket called.
std::string call_words(const ShotCall& call, GameType game) {
    if (call.push_out)
        return ", push-out";
    if (call.call.safety)
        return ", safety";
    if (call.call.ball > 0 && call.call.pocket > 0)
        return ", calls the " + ball_words(call.call.ball, game) + " in the " +
               pocket_name(call.call.pocket);
    if (call.call.ball > 0 && game_row(game).calls == CallRule::ball_on)
        return ", nominates " + ball_words(call.call.ball, game);
    return "";
}

std::string shot_line(int number, const PlayedShot& shot, const GameRecord& record) {
    const GameType game = record.setup.game;
    std::string line = std::to_string(number) + ". " + record.names[shot.shooter == 2 ? 1 : 0] +
                       (shot.was_break ? std::string(", ") + game_row(game).words.break_shot : "") +
                       call_words(shot.call, game) + ": ";
    if (shot.verdict.pocketed.empty()) {
        line += "nothing pocketed";
    } else {
        line += "pocketed";
        for (const int id : shot.verdict.pocketed)
            line += " " + (id == 0 ? std::string("cue ball") : ball_words(id, game));
    }
    return line + " \u2014 " + verdict_message(shot.verdict, shot.shooter, record.names);
}

} // namespace

std::vector<std::string> rack_log(const GameRecord& record, int rack) {
    std::vector<std::string> lines;
    int number = 0;
    const auto heard = [&](const PlayedShot& shot) {
        if (shot.rack == rack)
            lines.push_back(shot_line(++number, shot, record));
    };
    if (!std::holds_alternative<Match>(Match::replay(record, record.actions.size(), heard)))
        return {};
    return lines;
}

std::vector<std::size_t> log_page_starts(const std::vector<std::string>& lines, int width,
                                         int height) {
    // Rows for shots: the border (2), the title and the blank line after it, the blank line and
    // the footer at the end, and three rows to spare so that the box can stand clear of the
    // balls.
    const int rows = std::max(3, height - 9);
    // The box is as wide as its widest line, up to the screen less its border and a space
    // either side (draw_box): a line is wrapped only at that width.
    const int inner = std::max(1, width - 4);
    std::vector<std::size_t> starts{0};
    int used = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const int need = std::max(1, static_cast<int>(box_lines(lines[i], inner).size()));
        if (used > 0 && used + need > rows) {
            starts.push_back(i);
            used = 0;
        }
        used += need;
    }
    return starts;
}

void RackLog::rebuild(const GameRecord& record, int rack) {
    rack_ = rack;
    lines_ = rack_log(record, rack);
}

void RackLog::add(const PlayedShot& shot, const GameRecord& record) {
    if (shot.rack != rack_) {
        rack_ = shot.rack;
        lines_.clear();
    }
    lines_.push_back(shot_line(static_cast<int>(lines_.size()) + 1, shot, record));
}

std::vector<std::string> RackLog::lines(int rack) const {
    return rack == rack_ ? lines_ : std::vector<std::string>{};
}

} // namespace termpool::tui
