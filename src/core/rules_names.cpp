#include <termpool/rules.hpp>
#include <termpool/rules_names.hpp>

namespace termpool {

const char* game_type_name(GameType type) {
    switch (type) {
    case GameType::eight_ball:
        return "8ball";
    case GameType::eight_ball_bar:
        return "8ball-bar";
    case GameType::nine_ball:
        return "9ball";
    case GameType::snooker:
        return "snooker";
    case GameType::ten_ball:
        return "10ball";
    }
    return "?";
}

std::optional<GameType> parse_game_type(const std::string& name) {
    for (const GameType t : {GameType::eight_ball, GameType::eight_ball_bar, GameType::nine_ball,
                             GameType::ten_ball, GameType::snooker})
        if (name == game_type_name(t))
            return t;
    // 10-ball's other spellings; the name written is "10ball", like "9ball".
    if (name == "ten-ball" || name == "10-ball")
        return GameType::ten_ball;
    return std::nullopt;
}

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
