#pragma once
// Where the actions at a table go and come from. The App turns every input into an action and
// submits it to one driver; the driver applies it (local play: the Match, the save, the
// statistics), sends it (the hall: the server, whose echo comes back), or plays a practice
// table. Actions of others (the computer's, the other terminal's, a record's) come from the
// driver as `upcoming`, for the App to show at a player's pace before it takes them.

#include <chrono>
#include <optional>
#include <string>
#include <termpool/level.hpp>
#include <termpool/match.hpp>
#include <termpool/record.hpp>
#include <vector>

#include "tui/terminal.hpp"
#include "tui/view.hpp"

namespace termpool::tui {

/// One action taken at the table, for the App to show.
struct TableNews {
    RecordedAction action;                ///< what was done
    int actor = 0;                        ///< who did it: 1 or 2
    std::optional<PlayedShot> shot;       ///< a shot: its simulation and (with a referee) verdict
    std::optional<Trajectory> trajectory; ///< a shot: its balls' paths, to roll it out
    std::optional<Game> before;           ///< a shot: the game as it stood before it
    MatchState score_before;              ///< a shot: the score as it stood before it
    std::string words;                    ///< what to tell once it is shown (a verdict, a choice)
};

/// An action someone else has decided and the table has not yet taken.
struct Upcoming {
    RecordedAction action; ///< what will be done
    bool paced = false;    ///< a computer's: shown like a player's (the cue turns, the bar fills)
    bool hurry = false;    ///< the terminal is far behind: a shot comes to rest at once
};

/// Another terminal's cue, as it sets it.
struct SeatAim {
    int seat = 0;  ///< the seat aiming: 1 or 2
    Strike strike; ///< its cue as set
};

/// What a driver's own key did, for the App.
struct DriverReply {
    std::string words;             ///< for the message line
    bool new_turn = false;         ///< the table changed: the turn starts again
    std::optional<Strike> set_aim; ///< the cue to set (practice: a shot taken again)
};

/// What the App's screen is doing, for the drivers' part of the View.
struct ScreenFacts {
    bool rolling = false;  ///< a shot rolls
    bool over = false;     ///< the rack or game is over
    bool choosing = false; ///< a choice's box shows
    bool asking = false;   ///< a question (quit, concede) shows
};

/// The table's source of truth and the way to it.
class TableDriver {
public:
    using Clock = std::chrono::steady_clock;
    virtual ~TableDriver() = default;

    /// The match: seats, names, score, record (practice: its players only).
    virtual const Match& match() const = 0;
    /// The game shown.
    virtual const Game& game() const { return match().game(); }
    /// What the table waits for.
    virtual PendingAction pending() const { return match().pending(); }
    /// False without a referee (practice): no calls, no score, no log.
    virtual bool referee() const { return true; }
    /// True when this terminal acts for the player to act now.
    virtual bool may_act() const = 0;
    /// True when the shooter's call and nomination are known here (not another terminal's).
    virtual bool shows_call() const { return true; }
    /// True when nobody at this terminal plays (a replay, a spectator): each verdict replaces
    /// the last, as nobody acts to clear them.
    virtual bool watching() const { return false; }
    /// True when a shot at `ball` names its pocket.
    virtual bool calls_pocket(int ball) const { return match().calls_pocket(ball); }
    /// The balls the shooter may aim at first.
    virtual std::vector<int> targets() const { return game().legal_targets(); }

    /// The player here acts: the news when it was taken at once, nothing when it is on its way
    /// (its news comes as `upcoming`); `refusal` says why it was not taken.
    virtual std::optional<TableNews> submit(const RecordedAction& action, std::string& refusal) = 0;
    /// The next action of someone else, decided and not yet taken (null: none now).
    virtual const Upcoming* upcoming(Clock::time_point now) = 0;
    /// Takes the upcoming action; nothing when it could not be (the hall asks again).
    virtual std::optional<TableNews> take() = 0;

    /// A new game between the same seats, `breaker` to break; false where the table cannot.
    virtual bool rematch(int /*breaker*/) { return false; }
    /// True when the players may be renamed here.
    virtual bool may_rename() const { return false; }
    /// Renames `player`.
    virtual MatchError rename(int /*player*/, const std::string& /*name*/) {
        return MatchError::not_offered;
    }
    /// Seats a computer of `level` in `player`'s seat (named after it).
    virtual MatchError seat_computer(int /*player*/, Level /*level*/) {
        return MatchError::not_offered;
    }
    /// Sets the race before the first action.
    virtual MatchError set_race(int /*race_to*/) { return MatchError::not_offered; }

    /// A key or click of the driver's own (the hall's chat, practice's moves, the replay's
    /// stepping); nothing when it is not one.
    virtual std::optional<DriverReply> handle(const Input& /*in*/, const Layout& /*layout*/,
                                              const ScreenFacts& /*screen*/) {
        return std::nullopt;
    }
    /// The cue as the player here sets it (the hall shows it at the other terminal).
    virtual void aim_set(const Strike& /*strike*/) {}
    /// The other terminal's latest cue, once (the hall's other seat).
    virtual std::optional<SeatAim> take_seat_aim() { return std::nullopt; }
    /// True once after the table was replaced under the App (the hall's record, a replay's
    /// step back): the turn starts again from `table_words`.
    virtual bool take_reset() { return false; }
    /// Where the table stands, in words.
    virtual std::string table_words() const { return {}; }
    /// A message for the message line, once (the hall's refusal).
    virtual std::string take_message() { return {}; }
    /// A notice shown first, until it clears (the hall's connection).
    virtual std::string notice() const { return {}; }
    /// Why the game is not being kept, until it is again.
    virtual std::string problem() const { return {}; }
    /// True while the driver has news to show by itself (frames are due often).
    virtual bool busy() const { return false; }
    /// Adds the driver's part to the View (the hall's seats and chat, the replay's place).
    virtual void compose(View& /*view*/, const ScreenFacts& /*screen*/) const {}
    /// The box at the end of a rack or game (`told`: its verdict); empty: no box.
    virtual std::string game_over_text(const std::string& told) const = 0;
    /// The question before leaving; empty: leave at once.
    virtual std::string quit_question() const { return "Quit the game?  y / n"; }
    /// The session ends: what must be kept is kept.
    virtual void leave() {}
};

} // namespace termpool::tui
