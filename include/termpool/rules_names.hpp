#pragma once
/// \file
/// The referee's words, one table an enum: the names `termpool simulate`, a game record and
/// the hall write ("wrong-ball-first", "play-on", ...), read back by `parse_name`.

#include <termpool/enum_names.hpp>
#include <termpool/rules.hpp>

namespace termpool {

/// An 8-ball group's names.
inline constexpr NameRow<Group> group_names[] = {
    {Group::open, "open"},
    {Group::solids, "solids"},
    {Group::stripes, "stripes"},
};
static_assert(names_in_order(group_names));

/// Player 1's group, as a scenario's `groups` line and `termpool simulate`'s verdict give it:
/// the "1=" keeps the words unambiguous, naming player 1's group whoever shoots.
inline constexpr NameRow<Group> player1_group_names[] = {
    {Group::open, "open"},
    {Group::solids, "1=solids"},
    {Group::stripes, "1=stripes"},
};
static_assert(names_in_order(player1_group_names));

/// The names of where the cue ball goes in hand.
inline constexpr NameRow<BallInHand> ball_in_hand_names[] = {
    {BallInHand::none, "none"},
    {BallInHand::kitchen, "kitchen"},
    {BallInHand::anywhere, "anywhere"},
    {BallInHand::d, "d"},
};
static_assert(names_in_order(ball_in_hand_names));

/// The fouls' names.
inline constexpr NameRow<Foul> foul_names[] = {
    {Foul::none, "none"},
    {Foul::scratch, "scratch"},
    {Foul::cue_off_table, "cue-off-table"},
    {Foul::off_table, "off-table"},
    {Foul::no_contact, "no-contact"},
    {Foul::wrong_ball_first, "wrong-ball-first"},
    {Foul::no_rail, "no-rail"},
    {Foul::bad_break, "bad-break"},
    {Foul::pot_not_on, "pot-not-on"},
    {Foul::free_ball_snooker, "free-ball-snooker"},
};
static_assert(names_in_order(foul_names));

/// The choices' names, as a record's `choose` line gives them.
inline constexpr NameRow<Choice> choice_names[] = {
    {Choice::play_on, "play-on"},
    {Choice::re_rack, "re-rack"},
    {Choice::re_break, "re-break"},
    {Choice::spot_eight, "spot-eight"},
    {Choice::take_solids, "take-solids"},
    {Choice::take_stripes, "take-stripes"},
    {Choice::shoot, "shoot"},
    {Choice::pass_back, "pass-back"},
    {Choice::offender_plays, "offender-plays"},
    {Choice::replace_and_replay, "replace-and-replay"},
    {Choice::concede, "concede"},
};
static_assert(names_in_order(choice_names));

/// The names of why a game ended.
inline constexpr NameRow<WinReason> win_reason_names[] = {
    {WinReason::none, "none"},
    {WinReason::eight_pocketed, "eight-pocketed"},
    {WinReason::eight_on_break, "eight-on-break"},
    {WinReason::eight_early, "eight-early"},
    {WinReason::eight_on_foul, "eight-on-foul"},
    {WinReason::eight_wrong_pocket, "eight-wrong-pocket"},
    {WinReason::eight_off_table, "eight-off-table"},
    {WinReason::nine_pocketed, "nine-pocketed"},
    {WinReason::three_fouls, "three-fouls"},
    {WinReason::ten_pocketed, "ten-pocketed"},
    {WinReason::frame_won, "frame-won"},
    {WinReason::conceded, "conceded"},
    {WinReason::three_misses, "three-misses"},
};
static_assert(names_in_order(win_reason_names));

/// Snooker: the names of what the shooter is on.
inline constexpr NameRow<BallOn> ball_on_names[] = {
    {BallOn::red, "red"},
    {BallOn::colour, "colour"},
    {BallOn::in_order, "in-order"},
};
static_assert(names_in_order(ball_on_names));

} // namespace termpool
