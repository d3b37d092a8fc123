#pragma once
/// \file
/// Display width of UTF-8 text, without curses or the C locale: what lays text out in columns
/// (a player's name, a table of figures) must agree with what a terminal shows.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace termpool {

/// Decodes the UTF-8 sequence starting at s[i] into `cp` and advances `i` past it. Returns false
/// (advancing by one byte) for an invalid sequence: a stray continuation byte, a truncated
/// sequence, an overlong form, a surrogate or a value above U+10FFFF.
bool decode_utf8(std::string_view s, std::size_t& i, char32_t& cp);

/// Appends the UTF-8 encoding of `cp` (which must be a valid scalar value) to `out`.
void append_utf8(std::string& out, char32_t cp);

/// True when `s` is valid UTF-8 throughout.
bool valid_utf8(std::string_view s);

/// True for C0 controls, DEL and C1 controls (U+0080..U+009F).
bool is_control(char32_t cp);

/// Columns a code point takes: 0 for combining marks, zero-width characters and controls, 2 for
/// East Asian wide and full-width characters and most emoji, 1 otherwise.
int codepoint_width(char32_t cp);

/// Columns `s` takes on a terminal; an invalid byte counts as one column (it is shown as a
/// replacement character).
int display_width(std::string_view s);

/// The longest prefix of `s` no wider than `columns`, cut between code points (never inside a
/// UTF-8 sequence, never between a character and the combining marks that follow it).
std::string truncate_to_width(std::string_view s, int columns);

/// `text` broken into lines no wider than `columns`: at '\n', between words where possible,
/// inside a word only when it is wider than a line. Spaces at the breaks are dropped.
std::vector<std::string> wrap_to_width(std::string_view text, int columns);

} // namespace termpool
