#include "tui/messages.hpp"

#include <termpool/game_registry.hpp>
#include <termpool/snooker_layout.hpp>
#include <termpool/spots.hpp>

namespace termpool::tui {

std::string foul_words(Foul foul) {
    switch (foul) {
    case Foul::none:
        return "no foul";
    case Foul::scratch:
        return "scratch";
    case Foul::cue_off_table:
        return "cue ball off the table";
    case Foul::off_table:
        return "ball off the table";
    case Foul::no_contact:
        return "no ball hit";
    case Foul::wrong_ball_first:
        return "wrong ball first";
    case Foul::no_rail:
        return "no rail after contact";
    case Foul::bad_break:
        return "illegal break";
    case Foul::pot_not_on:
        return "potted a ball not on";
    case Foul::free_ball_snooker:
        return "snookered with the free ball";
    }
    return "foul";
}

std::string choice_words(Choice choice) {
    switch (choice) {
    case Choice::play_on:
        return "play on";
    case Choice::re_rack:
        return "re-rack and break";
    case Choice::re_break:
        return "the breaker breaks again"; // offered to the breaker (the 8 on the break) or not

    case Choice::spot_eight:
        return "spot the 8 and shoot";
    case Choice::take_solids:
        return "take solids";
    case Choice::take_stripes:
        return "take stripes";
    case Choice::shoot:
        return "shoot from here";
    case Choice::pass_back:
        return "pass the shot back";
    case Choice::offender_plays:
        return "the offender plays again";
    case Choice::replace_and_replay:
        return "replace the balls, the offender plays again";
    case Choice::concede:
        return "concede the frame";
    }
    return "?";
}

std::string choice_words(Choice choice, GameType game, bool free_ball, BallInHand in_hand) {
    if (game_row(game).scoring != Scoring::points)
        return choice_words(choice);
    // As a snooker referee asks after a foul; after an in-off whoever plays places the cue ball
    // in the D first.
    const bool in_d = in_hand == BallInHand::d;
    switch (choice) {
    case Choice::play_on:
        return in_d        ? "play on, the cue ball in hand in the D"
               : free_ball ? "play on, with a free ball"
                           : "play on from here";
    case Choice::offender_plays:
        return in_d ? "put the offender back in, the cue ball in the D"
                    : "put the offender back in";
    case Choice::replace_and_replay:
        return "replace the balls, the offender plays again (a miss)";
    default:
        return choice_words(choice);
    }
}

std::string snooker_ball_name(int id) {
    static const char* const colours[] = {"yellow", "green", "brown", "blue", "pink", "black"};
    if (is_snooker_red(id))
        return "red";
    if (is_snooker_colour(id))
        return colours[id - snooker_yellow];
    return "";
}

std::string ball_in_hand_words(BallInHand where) {
    switch (where) {
    case BallInHand::d:
        return "in the D";
    case BallInHand::kitchen:
        return "in the kitchen";
    case BallInHand::anywhere:
        return "anywhere";
    case BallInHand::none:
        break;
    }
    return "";
}

std::string win_message(const Verdict& v, int shooter, const std::string names[2]) {
    const std::string& who = names[shooter - 1];
    const std::string& winner = names[v.winner - 1];
    const std::string tail = " \u2014 " + winner + " wins";
    switch (v.reason) {
    case WinReason::eight_pocketed:
        return who + " pocketed the 8" + tail;
    case WinReason::eight_on_break:
        return who + " pocketed the 8 on the break" + tail;
    case WinReason::eight_early:
        return who + " pocketed the 8 early" + tail;
    case WinReason::eight_on_foul:
        return who + " fouled with the 8" + tail;
    case WinReason::eight_wrong_pocket:
        return who + " pocketed the 8 in a pocket not called" + tail;
    case WinReason::eight_off_table:
        return who + " drove the 8 off the table" + tail;
    case WinReason::nine_pocketed:
        return who + " pocketed the 9" + tail;
    case WinReason::ten_pocketed:
        return who + " pocketed the called 10" + tail;
    case WinReason::three_fouls:
        return who + " fouled three times in a row" + tail;
    case WinReason::frame_won:
        return winner + " wins the frame on points";
    case WinReason::conceded:
        return names[2 - v.winner] + " conceded" + tail;
    case WinReason::three_misses:
        return who + " missed three times running" + tail;
    case WinReason::none:
        break;
    }
    return winner + " wins";
}

std::string placement_problem(const Game& game, Vec2 spot) {
    if (game.legal_placement(spot))
        return "";
    if (game.ball_in_hand() == BallInHand::none)
        return "there is no ball in hand";
    const double R = game.params().ball_radius;
    if (!on_playing_surface(game.table(), spot, R))
        return "that is off the cloth";
    if (game.ball_in_hand() == BallInHand::kitchen && spot.x > game.table().head_string_x())
        return "in the kitchen only (left of the head string)";
    if (game.ball_in_hand() == BallInHand::d && !in_snooker_d(game.table(), spot))
        return "in the D only";
    if (const int touched = ball_touching(game.balls(), spot, R, 0); touched >= 0)
        return "it would touch the " + (game_row(game.type()).balls == BallSet::snooker
                                            ? snooker_ball_name(touched)
                                            : std::to_string(touched));
    return "not allowed there";
}

std::string verdict_message(const Verdict& v, int shooter, const std::string names[2]) {
    if (v.winner != 0)
        return win_message(v, shooter, names);
    const std::string& next = names[v.next_shooter - 1];
    if (v.stalemate_rerack)
        return "Stalemate: " + next + " breaks a new rack";
    if (v.foul != Foul::none && v.penalty > 0) {
        // Snooker: the points go to the opponent, who then chooses or plays from the D.
        const std::string& other = names[2 - shooter];
        // A snooker player says "in-off" where a pool player says "scratch".
        const std::string what = v.foul == Foul::scratch ? "in-off" : foul_words(v.foul);
        std::string m = std::string(v.miss ? "Foul and a miss: " : "Foul: ") + what + " \u2014 " +
                        std::to_string(v.penalty) + " points to " + other;
        if (v.chooser != 0)
            return m + "; " + names[v.chooser - 1] + " chooses";
        if (v.ball_in_hand == BallInHand::d)
            return m + "; " + next + " has ball in hand in the D";
        return m + "; " + next + " to play";
    }
    if (v.points > 0 && v.next_shooter == shooter)
        return names[shooter - 1] + " scores " + std::to_string(v.points) + " and plays on";
    if (v.foul != Foul::none) {
        std::string m = "Foul: " + foul_words(v.foul);
        if (v.ball_in_hand != BallInHand::none)
            return m + " \u2014 " + next + " has ball in hand" +
                   (v.ball_in_hand == BallInHand::kitchen ? " (kitchen)" : "");
        return m + " \u2014 " + next + " to shoot";
    }
    if (v.chooser != 0 && !v.legal_break)
        return "Illegal break (fewer than four balls to a rail): " + names[v.chooser - 1] +
               " chooses";
    if (v.chooser != 0)
        return names[v.chooser - 1] + " chooses";
    if (v.next_shooter != shooter)
        return "Switch player: " + next + " to shoot";
    if (v.groups_assigned) {
        Group mine = v.player1_group;
        if (v.next_shooter == 2 && mine != Group::open)
            mine = mine == Group::solids ? Group::stripes : Group::solids;
        return next + " has " + group_name(mine) + " \u2014 shoot again";
    }
    return next + " shoots again";
}

} // namespace termpool::tui
