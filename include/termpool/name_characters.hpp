#pragma once
/// \file
/// The characters a person's name may not hold: what would hide in it or turn the text around
/// it, so that two names that look alike are alike, and a name cannot reverse the line it is
/// shown on. No Unicode library: the sets are written out here (Unicode 15), and a test
/// compares them with ICU's.

#include <optional>
#include <string>
#include <string_view>

namespace termpool {

/// True for U+200E, U+200F, U+061C, U+202A..U+202E and U+2066..U+2069: the marks, embeddings,
/// overrides and isolates that change the direction in which text is shown.
bool is_bidi_control(char32_t cp);

/// True for a character that shows nothing or steers how others show: every
/// Default_Ignorable_Code_Point (U+200B zero width space, U+00AD soft hyphen, joiners,
/// variation selectors, tags, ...), every control (Cc: C0, DEL, C1), every format character
/// (Cf), and the line and paragraph separators (U+2028, U+2029). The bidirectional controls
/// are among them.
bool is_hidden_character(char32_t cp);

/// What is wrong with the characters of `name` as a person's name, in words that name the
/// first bad character ("a name may not hold U+202E (it changes the direction of the text)"),
/// or "a name needs a character that shows" when nothing of it does (spaces of any width,
/// marks alone); nothing when it is valid UTF-8 without hidden characters and something shows.
/// The length and the spaces at its ends are the callers' (`valid_player_name`).
std::optional<std::string> name_characters_problem(std::string_view name);

/// The same rule for any text a person sends to be shown to others, a chat line: nothing hidden
/// in it, nothing that turns the line it is shown on around or breaks it, and something that
/// shows; but the joiners (U+200C, U+200D) and variation selectors (U+FE00 to U+FE0F) that
/// emoji sequences and some scripts are written with pass. What is wrong, said of `subject`
/// ("chat is not valid UTF-8", "chat may not hold U+200B (an invisible character)", "chat of
/// nothing that shows says nothing"), or nothing.
std::optional<std::string> shown_text_problem(std::string_view text, std::string_view subject);

/// Whether every character of `text` may be in such a line (shown_text_problem but for the
/// line as a whole showing something): what a chat entry lets a key type.
bool text_characters_allowed(std::string_view text);

/// The widest name, in terminal columns (a CJK character counts two): the prompts take no key
/// past it, a name given on the command line is cut to it, and the hall refuses a wider one in
/// hello.
inline constexpr int max_name_columns = 20;

} // namespace termpool
