#pragma once
// The line the player types into at a prompt: a name, or the race's length.

#include <functional>
#include <string>

#include "tui/terminal.hpp"

namespace termpool::tui {

/// What is being typed, and for which question.
struct TextEntry {
    int player = 0;           ///< 1 or 2 while that player's name is typed, else 0
    bool asking_race = false; ///< the name prompt's last question: the race length
    std::string text;         ///< typed so far
    std::string error;        ///< why the last Enter was refused, shown under the prompt

    /// True while a prompt is open.
    bool active() const { return player != 0 || asking_race; }
    /// Typing and Backspace from `in`: true when `in` was one of them (typed text that
    /// `accept` refuses is dropped). Enter, Esc and the rest are the caller's.
    bool edit(const Input& in, const std::function<bool(const std::string& typed)>& accept = {});
    /// Appends typed text; a new keystroke clears the error.
    void type(const std::string& typed);
    /// Removes the last character (UTF-8: all its bytes).
    void erase_last();
    /// Empties the line and the error.
    void clear();
};

/// True for the keys that erase: Backspace in either of its codes.
bool is_backspace(int key);

} // namespace termpool::tui
