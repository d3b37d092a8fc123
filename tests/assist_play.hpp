#pragma once
// A player who only presses Space, headless: each turn opens as the game opens it (the cue ball
// in hand put where it is proposed, the first choice taken, the aim the assist opens with, the
// call the panel shows) and is shot at once. Against a computer, it measures how much of the
// game the assist plays by itself.

#include <cstdint>
#include <optional>
#include <termpool/match.hpp>
#include <termpool/record.hpp>
#include <variant>

#include "tui/aim.hpp"
#include "tui/aim_state.hpp"
#include "tui/cue_ball_spot.hpp"
#include "tui/shot_call.hpp"

namespace termpool::test {

/// What the Space presser did in one game.
struct SpaceOnlyGame {
    int shots = 0;    ///< its shots, the break included
    int potted = 0;   ///< balls it pocketed on shots without a foul
    int on_break = 0; ///< of those, on its break
    int fouls = 0;    ///< its shots that fouled
    int winner = 0;   ///< 1: the Space presser, 2: the computer, 0: not over in the shots allowed
};

/// Player 1 presses only Space under `assist` against the computer at `level` in seat 2, in
/// `game` racked from `seed` (the computer's stream from seed + 1, as the game seeds it),
/// until the game is over or `max_actions` actions have been taken.
inline SpaceOnlyGame space_only_game(GameType game, std::uint64_t seed, Assist assist, Level level,
                                     int max_actions = 400) {
    GameRecord header;
    header.setup.game = game;
    header.setup.table = game == GameType::snooker ? TableSize::snooker : TableSize::nine_foot;
    header.seed = seed;
    header.assist = assist;
    header.computers[1] = level;
    auto started = Match::start(header, seed + 1);
    Match& match = std::get<Match>(started);
    const Table& table = match.game().table();
    const PhysicsParams& params = match.game().params();
    tui::AimState aim;
    aim.assist = assist;
    SpaceOnlyGame out;
    for (int n = 0; n < max_actions; ++n) {
        const PendingAction pending = match.pending();
        if (pending.kind == Pending::over || pending.kind == Pending::next_rack)
            break;
        if (match.computer_to_act()) {
            const std::optional<ComputerMove> move = match.computer_move();
            if (!move)
                break;
            if (move->kind == Pending::place)
                match.place(2, move->spot);
            else if (move->kind == Pending::choose)
                match.choose(2, move->choice);
            else
                match.shoot(2, move->shot.strike, move->shot.call);
            continue;
        }
        const Game& g = match.game();
        if (pending.kind == Pending::choose) {
            match.choose(1, g.choices().front()); // "1"
            continue;
        }
        const Ball* cue = nullptr;
        for (const Ball& b : g.balls())
            if (b.id == 0)
                cue = &b;
        if (pending.kind == Pending::place) {
            const bool must_move =
                !cue || cue->state == MotionState::pocketed || !g.legal_placement(cue->position);
            match.place(1,
                        must_move ? tui::first_cue_ball_spot(g, table.head_spot()) : cue->position);
            continue;
        }
        // The turn opens as App::start_aiming opens it; Space shoots it as it stands.
        const std::vector<int> legal = g.legal_targets();
        const auto calls_pocket = [&](int ball) { return match.calls_pocket(ball); };
        aim.new_turn();
        aim.set_break(g.is_break());
        aim.aim_at_target(
            tui::rank_openings(table, g.balls(), params.ball_radius, cue->position, legal, assist));
        aim.update_preview(table, params, g.balls(), g.is_break(), calls_pocket);
        const ShotCall call = g.call_as_taken(tui::shot_call(aim, legal, calls_pocket).call);
        auto played = match.shoot(1, aim.set_strike(g.is_break()), call);
        const PlayedShot* shot = std::get_if<PlayedShot>(&played);
        if (!shot)
            break;
        ++out.shots;
        if (shot->verdict.foul != Foul::none)
            ++out.fouls;
        else
            out.potted += static_cast<int>(shot->verdict.pocketed.size());
        if (shot->was_break && shot->verdict.foul == Foul::none)
            out.on_break += static_cast<int>(shot->verdict.pocketed.size());
    }
    out.winner = match.game().winner();
    return out;
}

} // namespace termpool::test
