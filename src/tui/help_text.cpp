// help_text: the keys and mouse actions of the game.

#include "tui/help_text.hpp"

namespace termpool::tui {

const std::string& help_text() {
    static const std::string text = "Keys\n"
                                    "Left Right  h l   turn the aim 1 degree\n"
                                    "H L               turn the aim 0.1 degree\n"
                                    "Up Down  k j      more / less power\n"
                                    "Space  Enter      shoot\n"
                                    "[ ]               previous / next target ball\n"
                                    "w a s d           spin: follow, left, draw, right\n"
                                    "W A S D           the same in finer steps\n"
                                    "c                 centre the spin\n"
                                    "p                 power mode: distance / timed\n"
                                    "g                 aiming aid on / off\n"
                                    "1-6               call a pocket\n"
                                    "0                 call safety (on / off)\n"
                                    "u                 9-ball push-out after the break\n"
                                    "n                 rename a player\n"
                                    "x                 skip the animation\n"
                                    "?                 this help\n"
                                    "q                 quit\n"
                                    "\n"
                                    "Mouse\n"
                                    "move              aim at the pointer\n"
                                    "click, drag       aim there\n"
                                    "drag, release     distance mode: the pointer's\n"
                                    "                  distance sets the power, and\n"
                                    "                  releasing shoots\n"
                                    "[ shoot ]         click it to shoot";
    return text;
}

} // namespace termpool::tui
