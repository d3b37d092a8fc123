#include "player/stats_file.hpp"

#include "support/text_lines.hpp"
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <termpool/game_registry.hpp>
#include <unistd.h>

#include "files/atomic_file.hpp"
#include "files/file_limits.hpp"
#include "files/keep_aside.hpp"
#include "files/read_file.hpp"
#include "files/xdg_dir.hpp"
#include "player/save_file.hpp"
#include <termpool/text_width.hpp>

namespace termpool {
namespace {

// "8ball, 8ball-bar, 9ball, 10ball, snooker or mixed": the keys a line may give its game.
std::string known_game_keys() {
    std::string keys;
    for (const GameRow& row : game_registry().rows())
        keys += std::string(row.name) + ", ";
    return keys.substr(0, keys.size() - 2) + " or mixed";
}

constexpr std::string_view blanks = " \t\r\v\f";

// The next blank-separated field of `rest`, which is left after it.
std::string_view next_field(std::string_view& rest) {
    const std::size_t first = std::min(rest.find_first_not_of(blanks), rest.size());
    rest.remove_prefix(first);
    const std::size_t last = std::min(rest.find_first_of(blanks), rest.size());
    const std::string_view field = rest.substr(0, last);
    rest.remove_prefix(last);
    return field;
}

std::string_view trim(std::string_view s) {
    const std::size_t first = s.find_first_not_of(blanks);
    if (first == std::string_view::npos)
        return {};
    return s.substr(first, s.find_last_not_of(blanks) - first + 1);
}

// A count: digits only, at most what an int holds.
std::optional<int> parse_count(std::string_view field, std::string& error) {
    int value = 0;
    const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (field.empty() || !std::ranges::all_of(field, [](char c) { return c >= '0' && c <= '9'; }) ||
        (ec != std::errc() && ec != std::errc::result_out_of_range) ||
        end != field.data() + field.size()) {
        error = "'" + std::string(field) + "' is not a count";
        return std::nullopt;
    }
    if (ec == std::errc::result_out_of_range) {
        error = "count " + std::string(field) + " is too large";
        return std::nullopt;
    }
    return value;
}

std::string header() {
    return "termpool-stats " + std::to_string(stats_version);
}

} // namespace

const StatsEntry* StatsStore::find(std::string_view name, StatsGame game) const {
    const auto it = std::ranges::find_if(
        players, [&](const StatsEntry& e) { return e.name == name && e.game == game; });
    return it == players.end() ? nullptr : &*it;
}

std::string stats_name(std::string_view name) {
    std::string clean;
    for (std::size_t i = 0; i < name.size();) {
        char32_t cp;
        if (decode_utf8(name, i, cp) && !is_control(cp))
            append_utf8(clean, cp);
        else
            clean += '?';
    }
    const std::string_view trimmed = trim(clean);
    return trimmed.empty() ? "?" : std::string(trimmed);
}

std::string format_stats(const StatsStore& store) {
    std::string text = header() + "\n# player GAME COUNTS NAME; the counts of each game:\n";
    for (const StatsKind kind : {StatsKind::pool, StatsKind::snooker}) {
        text += "#";
        for (const GameType game : stats_game_order())
            if (stats_kind(game) == kind)
                text += " " + stats_game_key(game);
        if (kind == stats_kind_of(StatsGame{}))
            text += " " + stats_game_key(StatsGame{});
        text += ":";
        for (const StatsCount& c : stats_figures(kind).counts)
            text += std::string(" ") + c.key;
        text += "\n";
    }
    for (const StatsEntry& e : store.players) {
        text += "player " + stats_game_key(e.game);
        for (const StatsCount& c : stats_figures(stats_kind_of(e.game)).counts)
            text += " " + std::to_string(e.stats.*c.field);
        text += " " + stats_name(e.name) + "\n";
    }
    return text;
}

std::variant<StatsStore, StatsError> parse_stats(std::string_view text) {
    StatsStore store;
    std::vector<int> first_line; // the line of each entry, for a name listed twice
    int version = 0;             // 0 until the header
    int last_line = 0;
    for (const TextLine& line : text_lines(text)) {
        last_line = line.number;
        const std::string_view content = trim(line.text);
        if (content.empty() || content.front() == '#')
            continue;
        auto fail = [&](std::string message) {
            return StatsError{line.number, std::move(message)};
        };
        std::string_view rest = content;
        if (version == 0) {
            const std::string_view magic = next_field(rest), v = next_field(rest);
            if (magic != "termpool-stats" || v.empty() || !trim(rest).empty())
                return fail("not a termpool stats file (expected '" + header() + "')");
            std::string error;
            const auto read = parse_count(v, error);
            if (!read || *read < 1)
                return fail("bad version '" + std::string(v) + "'");
            if (*read > stats_version)
                return fail("written by a newer termpool (version " + std::string(v) +
                            "; this one reads " + std::to_string(stats_version) + ")");
            version = *read;
            continue;
        }
        const std::string_view keyword = next_field(rest);
        if (keyword != "player")
            return fail("unknown line '" + std::string(keyword) + "' (expected 'player')");
        StatsEntry entry;
        // Version 1 had no game: its totals were of all games together.
        if (version >= 2) {
            const std::string_view key = next_field(rest);
            if (key.empty())
                return fail("missing the game");
            if (!parse_stats_game_key(key, entry.game))
                return fail("unknown game '" + std::string(key) + "' (expected " +
                            known_game_keys() + ")");
        }
        const StatsFigures& figures = stats_figures(stats_kind_of(entry.game));
        for (const StatsCount& c : figures.counts) {
            const std::string_view field = next_field(rest);
            if (field.empty())
                return fail(std::string("missing the ") + c.name);
            std::string error;
            const auto count = parse_count(field, error);
            if (!count)
                return fail(std::string(c.name) + ": " + error);
            entry.stats.*c.field = *count;
        }
        const std::string_view name = trim(rest);
        if (name.empty())
            return fail("missing the player's name");
        if (!valid_utf8(name))
            return fail("the name is not valid UTF-8");
        if (stats_name(name) != name)
            return fail("control characters in the name");
        if (const auto problem = figures.contradiction(entry.stats))
            return fail(*problem);
        if (const StatsEntry* twice = store.find(name, entry.game))
            return fail(
                "'" + std::string(name) + "' is listed twice" +
                (version >= 2 ? " for " + stats_game_key(entry.game) : "") + " (first at line " +
                std::to_string(first_line[static_cast<std::size_t>(twice - store.players.data())]) +
                ")");
        entry.name = std::string(name);
        store.players.push_back(std::move(entry));
        first_line.push_back(line.number);
    }
    if (version == 0)
        return StatsError{std::max(last_line, 1),
                          "no '" + header() + "' line: not a stats file, or cut short"};
    return store;
}

void add_game(StatsStore& store, const std::string names[2], GameType game,
              const PlayerStats stats[2]) {
    // A type without a registry row (a test's game) has no name to be read back under: its
    // line would make the whole file unreadable.
    if (!game_registry().find(game))
        return;
    for (int p = 0; p < 2; ++p) {
        const std::string name = stats_name(names[p]);
        auto it = std::ranges::find_if(
            store.players, [&](const StatsEntry& e) { return e.name == name && e.game == game; });
        if (it == store.players.end()) {
            store.players.push_back({name, game, {}});
            it = store.players.end() - 1;
        }
        it->stats.add(stats[p]);
    }
}

bool remove_player(StatsStore& store, std::string_view name) {
    return std::erase_if(store.players, [&](const StatsEntry& e) { return e.name == name; }) > 0;
}

std::string stats_path() {
    return xdg_dir("XDG_STATE_HOME", ".local/state") + "/termpool/stats";
}

StatsFile read_stats_file(const std::string& path) {
    StatsFile file;
    std::string error;
    const std::optional<std::string> text = read_whole_file(path, error, max_stats_bytes);
    if (!text) {
        // Too large is no passing trouble: like a damaged file it is kept aside by the next
        // game, which starts new totals.
        struct stat st {};
        const bool too_large = ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
                               static_cast<unsigned long long>(st.st_size) > max_stats_bytes;
        file.state = error.empty() ? StatsFile::State::missing
                     : too_large   ? StatsFile::State::damaged
                                   : StatsFile::State::unreadable;
        file.problem = error;
        return file;
    }
    auto parsed = parse_stats(*text);
    if (const StatsError* bad = std::get_if<StatsError>(&parsed)) {
        file.state = StatsFile::State::damaged;
        file.problem = path + ":" + std::to_string(bad->line) + ": " + bad->message;
        return file;
    }
    file.state = StatsFile::State::read;
    file.store = std::move(std::get<StatsStore>(parsed));
    return file;
}

StatsLock::StatsLock(const std::string& path) {
    fd_ = ::open((path + ".lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0600);
    if (fd_ < 0)
        return;
    while (::flock(fd_, LOCK_EX) != 0 && errno == EINTR) {
    }
}

StatsLock::~StatsLock() {
    if (fd_ >= 0)
        ::close(fd_); // releases the lock
}

std::string save_game_stats(const std::string& path, const std::string names[2], GameType game,
                            const PlayerStats stats[2]) {
    const StatsLock lock(path);
    remove_temporaries_of(path); // what a writer killed midway left; none runs now
    StatsFile file = read_stats_file(path);
    std::string notice;
    switch (file.state) {
    case StatsFile::State::missing:
    case StatsFile::State::read:
        break;
    case StatsFile::State::unreadable:
        return file.problem + "; this game's statistics were not saved";
    case StatsFile::State::damaged: {
        std::string error;
        const auto aside = keep_aside(path, error);
        if (!aside)
            return file.problem + "; " + error + "; this game's statistics were not saved";
        notice = file.problem + "; kept as " + *aside + ", new totals started";
        break;
    }
    }
    add_game(file.store, names, game, stats);
    std::string error;
    if (!write_atomically(path, format_stats(file.store), error))
        return (notice.empty() ? "" : notice + "; ") + "could not save the statistics: " + error;
    return notice;
}

} // namespace termpool
