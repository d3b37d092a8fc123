#pragma once
/// \file
/// What a referee reads off a shot's events, once, before any rule is applied: the first ball
/// the cue ball met, the cushions, the pockets. Every game's referee judges from these facts.

#include <termpool/event.hpp>
#include <termpool/rules.hpp>
#include <vector>

namespace termpool {

/// The facts of one shot, read from its events (`from`).
struct ShotFacts {
    int first_contact = -1;          ///< first ball the cue ball touched, -1 for none
    std::vector<int> first_contacts; ///< all balls it touched at that same instant
    bool rail_after_contact = false; ///< a ball hit a cushion or jaw after the first contact
    int balls_to_rail = 0;           ///< distinct object balls that hit a cushion or jaw
    std::vector<int> pocketed;       ///< balls that dropped, in order (the cue ball too)
    std::vector<int> pockets;        ///< the pocket of each of them
    std::vector<int> off_table;      ///< balls that left the table
    std::vector<int> targets;        ///< balls the shooter could legally hit first

    /// True when ball `id` dropped.
    bool dropped(int id) const;
    /// The pocket ball `id` dropped in, 0 when it did not drop.
    int pocket_of(int id) const;
    /// True when an object ball (not the cue ball) dropped.
    bool object_ball_dropped() const;
    /// True when ball `id` left the table.
    bool left_table(int id) const;

    /// The facts of a shot with these `events` (the targets are left for the referee).
    static ShotFacts from(const std::vector<Event>& events);
    /// When the cue ball met several balls at once, the shooter gets the benefit of the doubt:
    /// the first contact is a legal target among them if there is one.
    void prefer_legal_first_contact();
    /// The fouls pool games share: cue ball pocketed or off the table, an object ball off the
    /// table, no contact, wrong ball first, no cushion after contact (a break is judged apart).
    std::vector<Foul> common_fouls() const;
};

} // namespace termpool
