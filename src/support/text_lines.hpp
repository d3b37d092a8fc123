#pragma once
/// \file
/// The line-oriented text formats (scenarios, game records, the config file, the statistics
/// file) read their input the same way: numbered lines, `#` comments, whitespace-separated
/// fields.

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace termpool {

/// One line of a text: its number (from 1) and its content, without the newline or a carriage
/// return before it.
struct TextLine {
    int number = 0;        ///< 1 for the first line
    std::string_view text; ///< a view into the text passed to text_lines
};

/// The lines of `text` in order; a last line without a newline counts too.
std::vector<TextLine> text_lines(std::string_view text);

/// `line` up to its `#` comment, if it has one.
std::string_view strip_comment(std::string_view line);

/// The fields of `line`, separated by runs of blanks (space, tab, CR, VT, FF).
std::vector<std::string_view> split_fields(std::string_view line);

/// The number of characters (code points) of `text` when it is valid UTF-8 without control
/// characters (C0, DEL, C1); nothing otherwise. Names and chat lines must pass it.
std::optional<std::size_t> printable_characters(std::string_view text);

} // namespace termpool
