#pragma once
/// \file
/// The text forms of a set of values, kept in one table: each row is a value, the name written
/// for it, and other spellings read as it. One template writes a name (`name_of`) and reads any
/// spelling (`parse_name`), so that what is written and what is read cannot drift apart.

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace termpool {

/// One value's row of a name table.
template <class T> struct NameRow {
    T value;          ///< the value named
    const char* name; ///< the name written, and read: a C string, for printf and std::string
    /// Other spellings read as the value, never written; the null ones are unused. (C strings,
    /// not string_views: GCC 12 cannot use a constexpr table whose rows default-construct a
    /// string_view.)
    std::array<const char*, 2> also{};
};

/// The name of `value` in `table`; `missing` when no row holds it (an enum value out of range).
template <class T, std::size_t N>
constexpr const char* name_of(const NameRow<T> (&table)[N], T value, const char* missing = "?") {
    for (const NameRow<T>& row : table)
        if (row.value == value)
            return row.name;
    return missing;
}

/// The value `text` spells in `table`, exactly (case and all), by its name or another spelling;
/// nothing for any other text.
template <class T, std::size_t N>
constexpr std::optional<T> parse_name(const NameRow<T> (&table)[N], std::string_view text) {
    for (const NameRow<T>& row : table) {
        if (text == row.name)
            return row.value;
        for (const char* other : row.also)
            if (other && text == other)
                return row.value;
    }
    return std::nullopt;
}

/// True when the rows of an enum's `table` are its values 0, 1, 2, ... in order, each once: a
/// table that passes `static_assert` next to its enum misses only values added after the last.
template <class T, std::size_t N> constexpr bool names_in_order(const NameRow<T> (&table)[N]) {
    for (std::size_t i = 0; i < N; ++i)
        if (static_cast<std::size_t>(table[i].value) != i)
            return false;
    return true;
}

/// `words` as a message lists them: "a", "a or b", "a, b or c".
inline std::string or_list(std::span<const std::string_view> words) {
    std::string list;
    for (std::size_t i = 0; i < words.size(); ++i)
        list += std::string(i == 0                  ? ""
                            : i + 1 == words.size() ? " or "
                                                    : ", ") +
                std::string(words[i]);
    return list;
}

/// The names of `table`'s rows as a message lists them: "physical, ideal or mirror".
template <class T, std::size_t N> std::string names_or_list(const NameRow<T> (&table)[N]) {
    std::array<std::string_view, N> names;
    for (std::size_t i = 0; i < N; ++i)
        names[i] = table[i].name;
    return or_list(names);
}

} // namespace termpool
