#pragma once
/// \file
/// Conversions between numbers and the text of the command-line tools, independent of the locale
/// (the game sets one for curses, and "1,5" must never be read as a number here).

#include "support/text_numbers.hpp"
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace termpool::cli {

/// `value` printed with `%.9g`, for figures people read (bench, experiment, messages); state
/// is written with format_double, which reads back exactly. Negative zero prints as "0".
std::string format_number(double value);

} // namespace termpool::cli
