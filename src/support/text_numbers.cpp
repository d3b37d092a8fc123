// Numbers in the project's text formats, read the same way everywhere and independent of the
// locale.
#include "text_numbers.hpp"
#include <algorithm>
#include <charconv>
#include <limits>
#include <system_error>

namespace termpool {
namespace {

// from_chars takes no '+'; people write "+0.3" for a tip offset, so accept one (but not "+-1").
std::string_view strip_plus(std::string_view text) {
    if (text.size() > 1 && text.front() == '+' && text[1] != '-' && text[1] != '+')
        text.remove_prefix(1);
    return text;
}

template <class T> std::optional<T> parse_whole_integer(std::string_view text) {
    text = strip_plus(text);
    T value{};
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc{} || end != text.data() + text.size() || text.empty())
        return std::nullopt;
    return value;
}

// The power of ten of the leading digit of a well-formed decimal number ("123.4e5" -> 7), only
// to tell overflow from underflow. A huge exponent saturates instead of overflowing.
long long decimal_exponent(std::string_view text) {
    if (text.front() == '-')
        text.remove_prefix(1);
    const std::size_t e = std::min(text.find_first_of("eE"), text.size());
    const std::string_view mantissa = text.substr(0, e);
    const std::size_t point = std::min(mantissa.find('.'), mantissa.size());
    long long leading = std::numeric_limits<long long>::min() / 2; // all zeros: tiny
    for (std::size_t i = 0; i < mantissa.size(); ++i) {
        if (mantissa[i] == '.' || mantissa[i] == '0')
            continue;
        leading =
            i < point ? static_cast<long long>(point - i) - 1 : -static_cast<long long>(i - point);
        break;
    }
    long long exponent = 0;
    if (e < text.size()) {
        std::string_view digits = text.substr(e + 1);
        const bool negative = digits.front() == '-';
        if (digits.front() == '-' || digits.front() == '+')
            digits.remove_prefix(1);
        const auto [end, ec] =
            std::from_chars(digits.data(), digits.data() + digits.size(), exponent);
        if (ec == std::errc::result_out_of_range)
            exponent = std::numeric_limits<long long>::max() / 2;
        if (negative)
            exponent = -exponent;
    }
    return leading + exponent;
}

} // namespace

std::optional<double> parse_double(std::string_view text) {
    text = strip_plus(text);
    if (text.empty())
        return std::nullopt;
    double value = 0;
    const char* last = text.data() + text.size();
    const auto [end, ec] = std::from_chars(text.data(), last, value);
    if (end != last)
        return std::nullopt;
    if (ec == std::errc::result_out_of_range) {
        // Too large is refused by the caller as not finite; too small is a zero.
        const double magnitude =
            decimal_exponent(text) > 0 ? std::numeric_limits<double>::infinity() : 0.0;
        return text.front() == '-' ? -magnitude : magnitude;
    }
    if (ec != std::errc{})
        return std::nullopt;
    return value;
}

std::string format_double(double value) {
    if (value == 0)
        value = 0; // turns -0 into +0
    // The longest shortest form of a double, "-2.2250738585072014e-308", has 24 characters.
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return ec == std::errc{} ? std::string(buffer, end) : "nan";
}

std::optional<long long> parse_integer(std::string_view text) {
    return parse_whole_integer<long long>(text);
}

std::optional<std::uint64_t> parse_uint64(std::string_view text) {
    return parse_whole_integer<std::uint64_t>(text);
}

std::optional<long long> parse_canonical_integer(std::string_view text) {
    const auto value = parse_integer(text);
    if (!value || std::to_string(*value) != text)
        return std::nullopt;
    return value;
}

std::optional<std::uint64_t> parse_canonical_uint64(std::string_view text) {
    const auto value = parse_uint64(text);
    if (!value || std::to_string(*value) != text)
        return std::nullopt;
    return value;
}

std::optional<double> parse_canonical_double(std::string_view text) {
    const auto value = parse_double(text);
    if (!value || format_double(*value) != text)
        return std::nullopt;
    return value;
}

} // namespace termpool
