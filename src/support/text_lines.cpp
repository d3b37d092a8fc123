#include "text_lines.hpp"
#include <algorithm>

namespace termpool {
namespace {

constexpr std::string_view blanks = " \t\r\v\f";

} // namespace

std::vector<TextLine> text_lines(std::string_view text) {
    std::vector<TextLine> lines;
    int number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        lines.push_back({++number, line});
        start = end + 1;
    }
    return lines;
}

std::string_view strip_comment(std::string_view line) {
    return line.substr(0, line.find('#'));
}

std::vector<std::string_view> split_fields(std::string_view line) {
    std::vector<std::string_view> fields;
    for (;;) {
        const std::size_t first = line.find_first_not_of(blanks);
        if (first == std::string_view::npos)
            return fields;
        line.remove_prefix(first);
        const std::size_t last = std::min(line.find_first_of(blanks), line.size());
        fields.push_back(line.substr(0, last));
        line.remove_prefix(last);
    }
}

std::optional<std::size_t> printable_characters(std::string_view text) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < text.size();) {
        const auto byte = static_cast<unsigned char>(text[i]);
        // The sequence length from the lead byte; overlong forms and surrogates are refused.
        const std::size_t length = byte < 0x80                   ? 1
                                   : byte >= 0xC2 && byte < 0xE0 ? 2
                                   : byte >= 0xE0 && byte < 0xF0 ? 3
                                   : byte >= 0xF0 && byte < 0xF5 ? 4
                                                                 : 0;
        if (length == 0 || i + length > text.size())
            return std::nullopt;
        char32_t code = length == 1 ? byte : byte & (0x7F >> length);
        for (std::size_t k = 1; k < length; ++k) {
            const auto next = static_cast<unsigned char>(text[i + k]);
            if ((next & 0xC0) != 0x80)
                return std::nullopt;
            code = (code << 6) | (next & 0x3F);
        }
        const char32_t lowest[] = {0, 0, 0x80, 0x800, 0x10000};
        if (code < lowest[length] || code > 0x10FFFF || (code >= 0xD800 && code < 0xE000))
            return std::nullopt;
        if (code < 0x20 || (code >= 0x7F && code < 0xA0))
            return std::nullopt; // C0, DEL, C1: they move the cursor or change a terminal's state
        i += length;
        ++count;
    }
    return count;
}

} // namespace termpool
