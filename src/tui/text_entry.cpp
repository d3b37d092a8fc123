#include "tui/text_entry.hpp"

#include "tui/terminal.hpp"

namespace termpool::tui {

void TextEntry::type(const std::string& typed) {
    text += typed;
    error.clear();
}

void TextEntry::erase_last() {
    while (!text.empty() && (text.back() & 0xC0) == 0x80)
        text.pop_back();
    if (!text.empty())
        text.pop_back();
}

void TextEntry::clear() {
    text.clear();
    error.clear();
}

bool is_backspace(int key) {
    return key == key_backspace || key == 8;
}

} // namespace termpool::tui
