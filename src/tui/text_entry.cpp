#include "tui/text_entry.hpp"

namespace termpool::tui {

bool TextEntry::edit(const Input& in, const std::function<bool(const std::string& typed)>& accept) {
    if (in.kind == Input::Kind::text) {
        if (!accept || accept(in.text))
            type(in.text);
        return true;
    }
    if (in.kind == Input::Kind::key && is_backspace(in.key)) {
        erase_last();
        return true;
    }
    return false;
}

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
