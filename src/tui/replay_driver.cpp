#include "tui/replay_driver.hpp"

#include <algorithm>

#include "tui/messages.hpp"
#include "tui/table_news.hpp"

namespace termpool::tui {
namespace {

// The record's own start: its header, no action.
Match start_of(const GameRecord& record) {
    auto replayed = Match::replay(record, 0);
    if (Match* m = std::get_if<Match>(&replayed))
        return std::move(*m);
    GameRecord header; // a record that cannot start (checked before): an empty game
    header.setup = record.setup;
    return std::get<Match>(Match::start(header));
}

bool is_shot(const RecordedAction& action) {
    return action.kind == RecordedAction::Kind::shot;
}

} // namespace

ReplayDriver::ReplayDriver(GameRecord record)
    : record_(std::move(record)), match_(start_of(record_)) {
    rewind_to(0);
}

void ReplayDriver::rewind_to(std::size_t action) {
    // Rebuild the match from the start without animation, up to (not including) `action`.
    next_ = std::min(action, record_.actions.size());
    std::optional<PlayedShot> last; // the shot the replay now stands after, to be told again
    auto replayed = Match::replay(record_, next_, [&](const PlayedShot& shot) { last = shot; });
    if (Match* m = std::get_if<Match>(&replayed))
        match_ = std::move(*m);
    upcoming_.reset();
    reset_ = true;
    if (last)
        message_ = verdict_message(last->verdict, last->shooter, record_.names) + ". " +
                   shot_words("after shot");
}

std::string ReplayDriver::shot_words(const std::string& which) const {
    const auto& all = record_.actions;
    const auto shot = std::count_if(all.begin(), all.begin() + static_cast<long>(next_), is_shot);
    const auto shots = std::count_if(all.begin(), all.end(), is_shot);
    return "Replay, " + which + " " + std::to_string(shot) + " of " + std::to_string(shots) +
           " (space pauses, Left/Right step, x skips, q quits)";
}

std::string ReplayDriver::table_words() const {
    return "Replay (space pauses, Left/Right step a shot, x skips, q quits)";
}

std::optional<TableNews> ReplayDriver::submit(const RecordedAction&, std::string& refusal) {
    refusal = "a replay only shows";
    return std::nullopt;
}

const Upcoming* ReplayDriver::upcoming(Clock::time_point) {
    if (paused_)
        return nullptr;
    if (upcoming_)
        return &*upcoming_;
    if (next_ >= record_.actions.size()) {
        message_ = "Replay ended: Left steps back, q quits";
        paused_ = true;
        return nullptr;
    }
    upcoming_ = Upcoming{record_.actions[next_], false, false};
    return &*upcoming_;
}

std::optional<TableNews> ReplayDriver::take() {
    if (!upcoming_)
        return std::nullopt;
    upcoming_.reset();
    const RecordedAction& action = record_.actions[next_++];
    MatchError error = MatchError::none;
    std::optional<TableNews> news = take_action(match_, action, error);
    if (news && is_shot(action))
        message_ = shot_words("shot");
    return news;
}

std::optional<DriverReply> ReplayDriver::handle(const Input& in, const Layout&,
                                                const ScreenFacts& screen) {
    if (in.kind == Input::Kind::text && in.text == " ") {
        paused_ = !paused_;
        return DriverReply{};
    }
    if (in.kind != Input::Kind::key || (in.key != key_left && in.key != key_right))
        return std::nullopt;
    // Step a whole shot: back to the start of the previous one, or on past the next.
    const std::vector<RecordedAction>& actions = record_.actions;
    const std::size_t shown = next_ - (screen.rolling ? 1 : 0);
    std::size_t shot_starts = 0, target = 0;
    for (std::size_t i = 0; i < actions.size(); ++i)
        if (is_shot(actions[i]) && i + 1 <= shown)
            shot_starts = i + 1;
    if (in.key == key_left) {
        for (std::size_t i = 0; i + 1 < shot_starts; ++i)
            if (is_shot(actions[i]))
                target = i + 1;
    } else {
        target = shot_starts;
        for (std::size_t i = shot_starts; i < actions.size(); ++i)
            if (is_shot(actions[i])) {
                target = i + 1;
                break;
            }
    }
    rewind_to(target);
    paused_ = true;
    return DriverReply{};
}

} // namespace termpool::tui
