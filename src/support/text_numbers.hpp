#pragma once
/// \file
/// Numbers in the project's text formats (scenarios, records, the command line), read the same
/// way everywhere and independent of the locale: the game sets one for curses, and "1,5" must
/// never be read as a number.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace termpool {

/// The whole of `text` read as a decimal or scientific number; a leading '+' is allowed.
/// "inf", "nan" and values too large for a double come back as infinity or NaN for the caller
/// to refuse with a message of its own. Nothing when `text` is not a number.
std::optional<double> parse_double(std::string_view text);

/// The shortest text that `parse_double` reads back to the same double (std::to_chars), for
/// every number of state that is written: simulate's output, records, setups, the hall's
/// messages. Negative zero prints as "0", so that outputs compare as text (it reads back as
/// +0); infinity and NaN print as "inf", "-inf" and "nan".
std::string format_double(double value);

/// The whole of `text` read as a decimal integer; nothing when it is not one or out of range.
std::optional<long long> parse_integer(std::string_view text);

/// The whole of `text` read as an unsigned 64-bit decimal integer; nothing when it is not one.
std::optional<std::uint64_t> parse_uint64(std::string_view text);

/// `parse_integer` held to the one text of each value, as `std::to_string` writes it: digits
/// without a leading zero ("0" only as itself), a '-' only before a value below zero, no '+'.
/// For the formats a program writes and another reads (the hall's messages, records of
/// version 6), where a second text for a value would be a second meaning to check.
std::optional<long long> parse_canonical_integer(std::string_view text);

/// `parse_uint64` held to the one text of each value (as `parse_canonical_integer`).
std::optional<std::uint64_t> parse_canonical_uint64(std::string_view text);

/// `parse_double` held to the one text of each value: only what `format_double` writes for it
/// ("0.5", not "+0.5", ".5", "0.50", "5e-1" or "-0").
std::optional<double> parse_canonical_double(std::string_view text);

} // namespace termpool
