#include "hall/hall_state.hpp"

#include "files/atomic_file.hpp"
#include "files/file_limits.hpp"
#include "files/keep_aside.hpp"
#include "files/read_file.hpp"
#include "hall/sha256.hpp"
#include "hall/socket_trust.hpp"

#include "support/text_lines.hpp"
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <optional>
#include <sys/random.h>
#include <sys/stat.h>
#include <termpool/match.hpp>
#include <unistd.h>
#include <variant>

namespace termpool::hall {
namespace {

constexpr const char* file_magic = "termpool-hall-table";
constexpr const char* hash_algorithm = "sha256";
constexpr std::size_t hash_hex_digits = 64;
// Table numbers the hall hands out stay far below this; a bigger one is a damaged file.
constexpr int max_table_number = 1'000'000;

std::string system_error(const std::string& path, const char* what = nullptr) {
    return path + ": " + (what ? std::string(what) + ": " : std::string()) + std::strerror(errno);
}

std::optional<int> table_number(std::string_view digits) {
    int n = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
    if (ec != std::errc() || end != digits.data() + digits.size() || n < 1 || n > max_table_number)
        return std::nullopt;
    return n;
}

// The number N of a name "table-N.save", written as table_path writes it (no leading zeros).
std::optional<int> number_of_file_name(std::string_view name) {
    const std::string_view prefix = "table-", suffix = ".save";
    if (!name.starts_with(prefix) || !name.ends_with(suffix))
        return std::nullopt;
    const auto n =
        table_number(name.substr(prefix.size(), name.size() - prefix.size() - suffix.size()));
    if (!n || name != "table-" + std::to_string(*n) + ".save")
        return std::nullopt;
    return n;
}

std::string format_table(const SavedTable& table) {
    std::string out = std::string(file_magic) + " " + std::to_string(hall_table_version) + "\n";
    out += "number " + std::to_string(table.number) + "\n";
    for (int p = 0; p < 2; ++p)
        if (!table.seat_tokens[p].empty())
            out += "seat" + std::to_string(p + 1) + "-token-hash " + hash_algorithm + " " +
                   table.seat_tokens[p] + "\n";
    return out + format_record(table.record);
}

// Reads a table file's text; `number` is the one its name gives.
std::variant<SavedTable, RecordError> parse_table(std::string_view text, int number) {
    SavedTable table;
    bool magic = false, numbered = false;
    int last_line = 1;
    for (const TextLine& line : text_lines(text)) {
        last_line = line.number;
        const std::vector<std::string_view> f = split_fields(strip_comment(line.text));
        if (f.empty())
            continue;
        auto fail = [&](std::string message) {
            return RecordError{line.number, std::move(message)};
        };
        if (!magic) {
            if (f[0] != file_magic)
                return fail("not a termpool hall table file");
            const auto version = f.size() == 2 ? table_number(f[1]) : std::nullopt;
            if (!version)
                return fail("table file version missing (a number from 1 expected)");
            if (*version > hall_table_version)
                return fail("table file version " + std::to_string(*version) +
                            " is newer than this termpool reads (" +
                            std::to_string(hall_table_version) + ")");
            magic = true;
        } else if (f[0] == "number" && f.size() == 2) {
            if (numbered)
                return fail("a second 'number' line");
            const auto n = table_number(f[1]);
            if (!n)
                return fail("bad table number");
            if (*n != number)
                return fail("table number " + std::to_string(*n) +
                            " does not match the file's name (table " + std::to_string(number) +
                            ")");
            numbered = true;
        } else if ((f[0] == "seat1-token-hash" || f[0] == "seat2-token-hash") && f.size() == 3) {
            if (f[1] != hash_algorithm)
                return fail("unknown token hash '" + std::string(f[1]) + "' (" + hash_algorithm +
                            " expected)");
            if (!valid_seat_token_hash(f[2]))
                return fail("a token hash is " + std::to_string(hash_hex_digits) +
                            " lowercase hex digits");
            std::string& slot = table.seat_tokens[f[0][4] - '1'];
            if (!slot.empty())
                return fail("a second " + std::string(f[0]) + " line");
            slot = f[2];
        } else if (f[0] == "termpool-record") {
            if (!numbered)
                return fail("no 'number' line before the record");
            // The record's own lines, counted from the top of the file in messages.
            const int before = line.number - 1;
            const auto record =
                parse_record(text.substr(static_cast<std::size_t>(line.text.data() - text.data())));
            if (const auto* error = std::get_if<RecordError>(&record))
                return RecordError{error->line + before, error->message};
            table.record = std::get<GameRecord>(record);
            const auto replayed = Match::replay(table.record);
            if (const auto* error = std::get_if<RecordError>(&replayed))
                return RecordError{error->line == 0 ? line.number : error->line + before,
                                   error->message};
            table.number = number;
            return table;
        } else {
            return fail("unknown or malformed line '" + std::string(f[0]) + "'");
        }
    }
    return RecordError{last_line, magic ? "truncated: no record" : "empty: not a table file"};
}

} // namespace

std::string default_state_dir() {
    if (const char* state = std::getenv("XDG_STATE_HOME"); state && *state)
        return std::string(state) + "/termpool/hall";
    const char* home = std::getenv("HOME");
    return std::string(home && *home ? home : ".") + "/.local/state/termpool/hall";
}

std::string new_seat_token() {
    unsigned char bytes[16];
    std::size_t got = 0;
    while (got < sizeof bytes) {
        const ssize_t n = ::getrandom(bytes + got, sizeof bytes - got, 0);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return {};
        got += static_cast<std::size_t>(n);
    }
    std::string token;
    for (const unsigned char b : bytes) {
        static const char digits[] = "0123456789abcdef";
        token += digits[b >> 4];
        token += digits[b & 15];
    }
    return token;
}

std::string seat_token_hash(std::string_view token) {
    return sha256_hex(token);
}

bool valid_seat_token_hash(std::string_view hash) {
    return hash.size() == hash_hex_digits && std::all_of(hash.begin(), hash.end(), [](char c) {
               return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
           });
}

std::string table_path(const std::string& dir, int number) {
    return dir + "/table-" + std::to_string(number) + ".save";
}

std::string save_table(const std::string& dir, const SavedTable& table) {
    const std::string path = table_path(dir, table.number);
    if (table.number < 1 || table.number > max_table_number)
        return path + ": table number " + std::to_string(table.number) + " out of range (1 to " +
               std::to_string(max_table_number) + ")";
    for (int p = 0; p < 2; ++p)
        if (!table.seat_tokens[p].empty() && !valid_seat_token_hash(table.seat_tokens[p]))
            return path + ": seat " + std::to_string(p + 1) + "'s token hash is not " +
                   std::to_string(hash_hex_digits) + " lowercase hex digits";
    std::string error;
    write_atomically(path, format_table(table), error);
    return error;
}

void forget_table(const std::string& dir, int number) {
    const std::string path = table_path(dir, number);
    ::unlink(path.c_str());
    remove_temporaries_of(path); // what a save killed midway left
}

namespace {

// The text of the table file at `path`. Only the server writes here, never a link: one is
// refused like a damaged file, and so is a file of someone else's (put there while the folder
// was open to them).
std::optional<std::string> read_table_file(const std::string& path, uid_t user,
                                           std::string& problem) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) == 0) {
        problem = judge_table_file(path, st, user);
        if (!problem.empty())
            return std::nullopt;
    }
    return read_whole_file(path, problem, max_save_bytes, Links::no_follow);
}

} // namespace

std::vector<SavedTable> load_tables(const std::string& dir, std::vector<std::string>& problems,
                                    uid_t user) {
    std::vector<int> numbers, left_temporaries;
    if (DIR* folder = ::opendir(dir.c_str())) {
        while (const dirent* entry = ::readdir(folder)) {
            const std::string_view name = entry->d_name;
            if (const auto n = number_of_file_name(name))
                numbers.push_back(*n);
            else if (const std::size_t mark = name.find(".save.tmp"); mark != name.npos)
                if (const auto of = number_of_file_name(name.substr(0, mark + 5)))
                    left_temporaries.push_back(*of);
        }
        ::closedir(folder);
    } else {
        if (errno != ENOENT)
            problems.push_back(system_error(dir, "cannot read the state folder"));
        return {};
    }
    // The folder's one server is starting: no save is running, so every temporary file is
    // what a killed one left.
    for (const int number : left_temporaries)
        remove_temporaries_of(table_path(dir, number));
    std::sort(numbers.begin(), numbers.end());
    std::vector<SavedTable> tables;
    for (const int number : numbers) {
        const std::string path = table_path(dir, number);
        std::string problem;
        if (const auto text = read_table_file(path, user, problem)) {
            auto table = parse_table(*text, number);
            if (auto* saved = std::get_if<SavedTable>(&table)) {
                tables.push_back(std::move(*saved));
                continue;
            }
            const RecordError& error = std::get<RecordError>(table);
            problem = path + ":" + std::to_string(error.line) + ": " + error.message;
        }
        std::string not_moved;
        if (const auto aside = keep_aside(path, not_moved))
            problem += " (moved aside as " + *aside + ")";
        else
            problem += " (it stays in place: " + not_moved + ")";
        problems.push_back(problem);
    }
    return tables;
}

} // namespace termpool::hall
