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

} // namespace termpool
