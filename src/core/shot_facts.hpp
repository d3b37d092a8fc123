#pragma once
// What the referee reads off a shot's events, once, before any rule is applied.

#include <termpool/rules.hpp>
#include <vector>

namespace termpool {

struct Game::Facts {
    int first_contact = -1;          // first ball the cue ball touched, -1 for none
    std::vector<int> first_contacts; // all balls it touched at that same instant
    bool rail_after_contact = false; // a ball hit a cushion or jaw after the first contact
    int balls_to_rail = 0;           // distinct object balls that hit a cushion or jaw
    std::vector<int> pocketed;       // balls that dropped, in order (the cue ball too)
    std::vector<int> pockets;        // the pocket of each of them
    std::vector<int> off_table;      // balls that left the table
    std::vector<int> targets;        // balls the shooter could legally hit first
    bool group_cleared = false;      // 8-ball: the shooter's group was all down before the shot
    int touching = -1;               // snooker: the ball on the cue ball rested against, or -1
    bool snookered_before = false;   // snooker: the shooter was snookered before the shot

    bool dropped(int id) const;
    int pocket_of(int id) const; // 0 when it did not drop
    bool object_ball_dropped() const;
    bool left_table(int id) const;

    static Facts from(const std::vector<Event>& events);
    // When the cue ball met several balls at once, the shooter gets the benefit of the doubt:
    // the first contact is a legal target among them if there is one.
    void prefer_legal_first_contact();
    // The fouls every game shares: cue ball pocketed or off the table, an object ball off the
    // table, no contact, wrong ball first, no cushion after contact (a break is judged apart).
    std::vector<Foul> common_fouls() const;
};

} // namespace termpool
