#include <termpool/rules.hpp>

namespace termpool {

const char* group_name(Group group) {
    switch (group) {
    case Group::open:
        return "open";
    case Group::solids:
        return "solids";
    case Group::stripes:
        return "stripes";
    }
    return "?";
}

const char* ball_in_hand_name(BallInHand bih) {
    switch (bih) {
    case BallInHand::none:
        return "none";
    case BallInHand::kitchen:
        return "kitchen";
    case BallInHand::anywhere:
        return "anywhere";
    case BallInHand::d:
        return "d";
    }
    return "?";
}

const char* foul_name(Foul foul) {
    switch (foul) {
    case Foul::none:
        return "none";
    case Foul::scratch:
        return "scratch";
    case Foul::cue_off_table:
        return "cue-off-table";
    case Foul::off_table:
        return "off-table";
    case Foul::no_contact:
        return "no-contact";
    case Foul::wrong_ball_first:
        return "wrong-ball-first";
    case Foul::no_rail:
        return "no-rail";
    case Foul::bad_break:
        return "bad-break";
    case Foul::pot_not_on:
        return "pot-not-on";
    case Foul::free_ball_snooker:
        return "free-ball-snooker";
    }
    return "?";
}

const char* choice_name(Choice choice) {
    switch (choice) {
    case Choice::play_on:
        return "play-on";
    case Choice::re_rack:
        return "re-rack";
    case Choice::re_break:
        return "re-break";
    case Choice::spot_eight:
        return "spot-eight";
    case Choice::take_solids:
        return "take-solids";
    case Choice::take_stripes:
        return "take-stripes";
    case Choice::shoot:
        return "shoot";
    case Choice::pass_back:
        return "pass-back";
    case Choice::offender_plays:
        return "offender-plays";
    case Choice::replace_and_replay:
        return "replace-and-replay";
    case Choice::concede:
        return "concede";
    }
    return "?";
}

const char* win_reason_name(WinReason reason) {
    switch (reason) {
    case WinReason::none:
        return "none";
    case WinReason::eight_pocketed:
        return "eight-pocketed";
    case WinReason::eight_on_break:
        return "eight-on-break";
    case WinReason::eight_early:
        return "eight-early";
    case WinReason::eight_on_foul:
        return "eight-on-foul";
    case WinReason::eight_wrong_pocket:
        return "eight-wrong-pocket";
    case WinReason::eight_off_table:
        return "eight-off-table";
    case WinReason::nine_pocketed:
        return "nine-pocketed";
    case WinReason::three_fouls:
        return "three-fouls";
    case WinReason::ten_pocketed:
        return "ten-pocketed";
    case WinReason::frame_won:
        return "frame-won";
    case WinReason::conceded:
        return "conceded";
    case WinReason::three_misses:
        return "three-misses";
    }
    return "?";
}

const char* ball_on_name(BallOn on) {
    switch (on) {
    case BallOn::red:
        return "red";
    case BallOn::colour:
        return "colour";
    case BallOn::in_order:
        return "in-order";
    }
    return "?";
}

std::vector<int> group_balls(Group group) {
    switch (group) {
    case Group::solids:
        return {1, 2, 3, 4, 5, 6, 7};
    case Group::stripes:
        return {9, 10, 11, 12, 13, 14, 15};
    case Group::open:
        break;
    }
    return {};
}

} // namespace termpool
