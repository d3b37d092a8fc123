#include "tui/table_news.hpp"

#include <termpool/game_registry.hpp>
#include <termpool/setup.hpp>

#include "tui/messages.hpp"

namespace termpool::tui {

std::optional<TableNews> take_action(Match& match, const RecordedAction& action, MatchError& error,
                                     int seat) {
    TableNews news;
    news.action = action;
    news.actor = match.to_act();
    // Said before the choice is taken: its words depend on what was offered.
    const std::string choice =
        choice_words(action.choice, match.game().type(), match.game().free_ball_offered(),
                     match.game().ball_in_hand());
    const int rack = match.rack();
    if (action.kind == RecordedAction::Kind::shot) {
        news.before = match.game();
        news.score_before = match.score();
        news.trajectory.emplace(game_physics(match.setup()), match.game().balls().size());
        news.shot.emplace();
    }
    error = match.apply(action, news.trajectory ? &*news.trajectory : nullptr,
                        news.shot ? &*news.shot : nullptr);
    if (error != MatchError::none)
        return std::nullopt;
    const std::string& who = match.name(news.actor);
    switch (action.kind) {
    case RecordedAction::Kind::shot:
        news.words = verdict_message(news.shot->verdict, news.shot->shooter, match.record().names);
        break;
    case RecordedAction::Kind::choose:
        news.words =
            action.choice == Choice::concede
                ? who + " concedes the frame \u2014 " + match.name(3 - news.actor) + " wins it"
                : who + " chooses: " + choice + "; " + next_words(match);
        break;
    case RecordedAction::Kind::rack:
        // Told to the breaker at this terminal, said to anyone else.
        news.words = match.rack() != rack
                         ? rack_words(match, action.breaker, seat != 0 && seat == action.breaker)
                         : "";
        break;
    case RecordedAction::Kind::place:
        break;
    }
    return news;
}

std::string breaks_words(const Match& match, int breaker, bool here) {
    const GameRow& row = game_row(match.game().type());
    const std::string breaks = match.name(breaker) + " " + row.words.breaks;
    // The player here is told what to do; of another seat it is said what it does ("breaks
    // off from the D").
    const std::string area = ball_in_hand_words(row.break_from);
    const std::string from = area.starts_with("in ") ? "from " + area.substr(3) : area;
    return here ? breaks + ": place the cue ball " + area : breaks + " " + from;
}

std::string rack_words(const Match& match, int breaker, bool here) {
    return std::string(game_row(match.game().type()).words.heading) + " " +
           std::to_string(match.rack()) + ": " + breaks_words(match, breaker, here);
}

std::string next_words(const Match& match) {
    const Game& g = match.game();
    const std::string& who = match.name(g.shooter());
    if (g.is_break())
        return who + " " + game_row(g.type()).words.breaks;
    if (g.ball_in_hand() != BallInHand::none)
        return who + " has ball in hand " + ball_in_hand_words(g.ball_in_hand());
    return who + " to shoot";
}

std::string standing_words(const Match& match) {
    const Game& g = match.game();
    if (const int winner = g.winner()) {
        if (match.pending().kind == Pending::next_rack)
            return match.name(winner) + " won rack " + std::to_string(match.rack());
        return match.name(winner) + " won";
    }
    if (const int chooser = g.chooser())
        return match.name(chooser) + " to choose";
    return match.name(g.shooter()) + " to play";
}

} // namespace termpool::tui
