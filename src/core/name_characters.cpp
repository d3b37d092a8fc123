// The characters a name may not hold, from the Unicode 15 tables (DerivedCoreProperties.txt's
// Default_Ignorable_Code_Point, UnicodeData.txt's Cc, Cf, Zl and Zp).
#include <algorithm>
#include <cstdio>
#include <iterator>
#include <termpool/name_characters.hpp>
#include <termpool/text_width.hpp>

namespace termpool {
namespace {

struct Range {
    char32_t first, last;
};

// The union of Default_Ignorable_Code_Point, Cc, Cf, Zl and Zp, in order, adjacent ranges
// merged.
constexpr Range hidden[] = {
    {0x0000, 0x001F},   {0x007F, 0x009F},   {0x00AD, 0x00AD},   {0x034F, 0x034F},
    {0x0600, 0x0605},   {0x061C, 0x061C},   {0x06DD, 0x06DD},   {0x070F, 0x070F},
    {0x0890, 0x0891},   {0x08E2, 0x08E2},   {0x115F, 0x1160},   {0x17B4, 0x17B5},
    {0x180B, 0x180F},   {0x200B, 0x200F},   {0x2028, 0x202E},   {0x2060, 0x206F},
    {0x3164, 0x3164},   {0xFE00, 0xFE0F},   {0xFEFF, 0xFEFF},   {0xFFA0, 0xFFA0},
    {0xFFF0, 0xFFFB},   {0x110BD, 0x110BD}, {0x110CD, 0x110CD}, {0x13430, 0x1343F},
    {0x1BCA0, 0x1BCA3}, {0x1D173, 0x1D17A}, {0xE0000, 0xE0FFF},
};

} // namespace

bool is_bidi_control(char32_t cp) {
    return cp == 0x061C || cp == 0x200E || cp == 0x200F || (cp >= 0x202A && cp <= 0x202E) ||
           (cp >= 0x2066 && cp <= 0x2069);
}

bool is_hidden_character(char32_t cp) {
    const auto after = std::upper_bound(std::begin(hidden), std::end(hidden), cp,
                                        [](char32_t c, const Range& r) { return c < r.first; });
    return after != std::begin(hidden) && cp <= std::prev(after)->last;
}

namespace {

// The joiners and variation selectors: invisible, but what emoji sequences ("❤️", a family)
// and scripts such as Persian are written with; harmless in a line of text, though a name,
// which must not look like another, holds none.
bool joins_or_selects(char32_t cp) {
    return cp == 0x200C || cp == 0x200D || (cp >= 0xFE00 && cp <= 0xFE0F);
}

// Unicode's space separators (Zs): blank however wide, as a space is.
bool is_space_separator(char32_t cp) {
    return cp == 0x0020 || cp == 0x00A0 || cp == 0x1680 || (cp >= 0x2000 && cp <= 0x200A) ||
           cp == 0x202F || cp == 0x205F || cp == 0x3000;
}

// The first problem of `text`: `invalid` for bad UTF-8, "HOLDER may not hold U+XXXX (why)",
// or `blank` (unless empty) when nothing of it shows (only spaces of any width, marks and
// joiners: a name or a line that would read as nobody's or as nothing); with `text_marks`,
// joiners and variation selectors pass.
std::optional<std::string> characters_problem(std::string_view text, std::string_view invalid,
                                              std::string_view holder, std::string_view blank,
                                              bool text_marks) {
    bool shows = false;
    for (std::size_t i = 0; i < text.size();) {
        char32_t cp = 0;
        if (!decode_utf8(text, i, cp))
            return std::string(invalid);
        shows = shows || (codepoint_width(cp) > 0 && !is_space_separator(cp));
        if (!is_hidden_character(cp) || (text_marks && joins_or_selects(cp)))
            continue;
        char code[16];
        std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(cp));
        // Said apart, as each is refused for its own reason.
        const char* what = is_control(cp)        ? " (a control character)"
                           : is_bidi_control(cp) ? " (it changes the direction of the text)"
                           : cp == 0x2028 || cp == 0x2029 ? " (a line or paragraph separator)"
                                                          : " (an invisible character)";
        return std::string(holder) + " may not hold " + code + what;
    }
    if (!shows && !text.empty() && !blank.empty())
        return std::string(blank);
    return std::nullopt;
}

} // namespace

std::optional<std::string> name_characters_problem(std::string_view name) {
    return characters_problem(name, "the name is not valid UTF-8", "a name",
                              "a name needs a character that shows", false);
}

std::optional<std::string> shown_text_problem(std::string_view text, std::string_view subject) {
    return characters_problem(text, std::string(subject) + " is not valid UTF-8", subject,
                              std::string(subject) + " of nothing that shows says nothing", true);
}

bool text_characters_allowed(std::string_view text) {
    // Only whether there is a problem is asked: no words, and no blank rule (a key alone may be
    // a space).
    return !characters_problem(text, "", "", "", true);
}

} // namespace termpool
