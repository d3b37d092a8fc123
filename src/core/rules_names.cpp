#include <termpool/rules.hpp>
#include <termpool/rules_names.hpp>

namespace termpool {

const char* group_name(Group group) {
    return name_of(group_names, group);
}

const char* ball_in_hand_name(BallInHand bih) {
    return name_of(ball_in_hand_names, bih);
}

const char* foul_name(Foul foul) {
    return name_of(foul_names, foul);
}

const char* choice_name(Choice choice) {
    return name_of(choice_names, choice);
}

const char* win_reason_name(WinReason reason) {
    return name_of(win_reason_names, reason);
}

const char* ball_on_name(BallOn on) {
    return name_of(ball_on_names, on);
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
