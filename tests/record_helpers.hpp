#pragma once
// Records made as the game makes them: computers play, each action goes into the record.

#include <termpool/computer.hpp>
#include <termpool/match.hpp>
#include <termpool/record.hpp>

namespace termpool::test {

// The player to act makes one move on `game`, and it goes into `record` as the game would save it.
/// `on_shot`, when given, hears each shot as a replay of the record would.
inline void play_one_action(Game& game, ComputerPlayer (&players)[2], GameRecord& record,
                            const ShotListener& on_shot = {}) {
    const int actor = game.chooser() != 0 ? game.chooser() : game.shooter();
    ComputerPlayer& player = players[actor - 1];
    RecordedAction action;
    if (game.chooser() != 0) {
        action.kind = RecordedAction::Kind::choose;
        action.choice = player.choose(game);
        game.choose(action.choice);
    } else if (game.ball_in_hand() != BallInHand::none && !game.ready_to_shoot()) {
        action.kind = RecordedAction::Kind::place;
        action.place = player.place_cue_ball(game);
        game.place_cue_ball(action.place);
    } else {
        const ComputerShot shot = player.shot(game);
        action.strike = shot.strike;
        action.call = shot.call;
        PlayedShot heard{game.shooter(), 1, game.is_break(), game.call_as_taken(shot.call), {}, {}};
        heard.verdict = game.play(shot.strike, shot.call, &heard.result);
        if (on_shot)
            on_shot(heard);
    }
    record.actions.push_back(action);
}

} // namespace termpool::test
