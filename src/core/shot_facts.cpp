#include <termpool/shot_facts.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>

namespace termpool {

bool ShotFacts::dropped(int id) const {
    return std::find(pocketed.begin(), pocketed.end(), id) != pocketed.end();
}

int ShotFacts::pocket_of(int id) const {
    for (std::size_t i = 0; i < pocketed.size(); ++i)
        if (pocketed[i] == id)
            return pockets[i];
    return 0;
}

bool ShotFacts::object_ball_dropped() const {
    return std::any_of(pocketed.begin(), pocketed.end(), [](int id) { return id != 0; });
}

bool ShotFacts::left_table(int id) const {
    return std::find(off_table.begin(), off_table.end(), id) != off_table.end();
}

void ShotFacts::prefer_legal_first_contact() {
    for (const int id : first_contacts) {
        if (std::find(targets.begin(), targets.end(), id) != targets.end()) {
            first_contact = id;
            return;
        }
    }
}

std::vector<Foul> ShotFacts::common_fouls() const {
    std::vector<Foul> fouls;
    if (dropped(0))
        fouls.push_back(Foul::scratch);
    if (left_table(0))
        fouls.push_back(Foul::cue_off_table);
    if (std::any_of(off_table.begin(), off_table.end(), [](int id) { return id != 0; }))
        fouls.push_back(Foul::off_table);
    if (first_contact < 0) {
        fouls.push_back(Foul::no_contact);
    } else {
        if (std::find(targets.begin(), targets.end(), first_contact) == targets.end())
            fouls.push_back(Foul::wrong_ball_first);
        if (!object_ball_dropped() && !rail_after_contact)
            fouls.push_back(Foul::no_rail);
    }
    return fouls;
}

ShotFacts ShotFacts::from(const std::vector<Event>& events) {
    ShotFacts f;
    // The object balls that met a cushion or jaw: a bit each for the ids a rack uses, a list for
    // any others (no list, and no allocation, for a shot of the computer's search).
    std::uint64_t railed_ids = 0;
    std::vector<int> railed_others;
    double first_time = 0;
    for (const Event& e : events) {
        switch (e.kind) {
        case EventKind::ball_ball:
            if (e.ball == 0 || e.other == 0) {
                const int object = e.ball == 0 ? e.other : e.ball;
                if (f.first_contact < 0) {
                    f.first_contact = object;
                    first_time = e.time;
                }
                // Contacts a nanosecond apart are simultaneous to any referee.
                if (e.time - first_time <= 1e-9)
                    f.first_contacts.push_back(object);
            }
            break;
        case EventKind::cushion:
        case EventKind::jaw:
            if (f.first_contact >= 0)
                f.rail_after_contact = true;
            if (e.ball > 0 && e.ball < 64)
                railed_ids |= std::uint64_t{1} << e.ball;
            else if (e.ball != 0 && std::find(railed_others.begin(), railed_others.end(), e.ball) ==
                                        railed_others.end())
                railed_others.push_back(e.ball);
            break;
        case EventKind::pocket:
            f.pocketed.push_back(e.ball);
            f.pockets.push_back(e.other);
            break;
        case EventKind::off_table:
            f.off_table.push_back(e.ball);
            break;
        default:
            break;
        }
    }
    f.balls_to_rail = std::popcount(railed_ids) + static_cast<int>(railed_others.size());
    return f;
}

} // namespace termpool
