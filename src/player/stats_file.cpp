#include "player/stats_file.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <fcntl.h>
#include <sys/file.h>
#include <termpool/text_lines.hpp>
#include <unistd.h>

#include "files/keep_aside.hpp"
#include "files/xdg_dir.hpp"
#include "player/save_file.hpp"
#include <termpool/text_width.hpp>

namespace termpool {
namespace {

constexpr std::string_view blanks = " \t\r\v\f";

// The figures of a player line, in file order, with their names for messages.
struct Figure {
    const char* name;
    int PlayerStats::*field;
};
constexpr Figure figures[] = {
    {"racks won", &PlayerStats::racks_won},
    {"racks played", &PlayerStats::racks_played},
    {"shots", &PlayerStats::shots},
    {"pot attempts", &PlayerStats::pot_attempts},
    {"pots made", &PlayerStats::pots_made},
    {"balls potted", &PlayerStats::balls_potted},
    {"fouls", &PlayerStats::fouls},
    {"break-and-runs", &PlayerStats::break_and_runs},
    {"longest run", &PlayerStats::longest_run},
};

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

// Figures that no game could produce: the file was edited or damaged.
std::optional<std::string> contradiction(const PlayerStats& s) {
    auto over = [](const char* a, int va, const char* b, int vb) {
        return std::string("more ") + a + " (" + std::to_string(va) + ") than " + b + " (" +
               std::to_string(vb) + ")";
    };
    if (s.racks_won > s.racks_played)
        return over("racks won", s.racks_won, "racks played", s.racks_played);
    if (s.pot_attempts > s.shots)
        return over("pot attempts", s.pot_attempts, "shots", s.shots);
    if (s.pots_made > s.pot_attempts)
        return over("pots made", s.pots_made, "pot attempts", s.pot_attempts);
    if (s.fouls > s.shots)
        return over("fouls", s.fouls, "shots", s.shots);
    if (s.break_and_runs > s.racks_won)
        return over("break-and-runs", s.break_and_runs, "racks won", s.racks_won);
    if (s.longest_run > s.balls_potted)
        return std::string("a longest run (") + std::to_string(s.longest_run) +
               ") longer than all balls potted (" + std::to_string(s.balls_potted) + ")";
    return std::nullopt;
}

std::string header() {
    return "termpool-stats " + std::to_string(stats_version);
}

} // namespace

const StatsEntry* StatsStore::find(std::string_view name) const {
    const auto it = std::ranges::find(players, name, &StatsEntry::name);
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
    std::string text = header() + "\n# won played shots attempts pots potted fouls "
                                  "break-and-runs longest-run name\n";
    for (const StatsEntry& e : store.players) {
        text += "player";
        for (const Figure& f : figures)
            text += " " + std::to_string(e.stats.*f.field);
        text += " " + stats_name(e.name) + "\n";
    }
    return text;
}

std::variant<StatsStore, StatsError> parse_stats(std::string_view text) {
    StatsStore store;
    std::vector<int> first_line; // the line of each entry, for a name listed twice
    bool have_header = false;
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
        if (!have_header) {
            const std::string_view magic = next_field(rest), v = next_field(rest);
            if (magic != "termpool-stats" || v.empty() || !trim(rest).empty())
                return fail("not a termpool stats file (expected '" + header() + "')");
            std::string error;
            const auto version = parse_count(v, error);
            if (!version || *version < 1)
                return fail("bad version '" + std::string(v) + "'");
            if (*version > stats_version)
                return fail("written by a newer termpool (version " + std::string(v) +
                            "; this one reads " + std::to_string(stats_version) + ")");
            have_header = true;
            continue;
        }
        const std::string_view keyword = next_field(rest);
        if (keyword != "player")
            return fail("unknown line '" + std::string(keyword) + "' (expected 'player')");
        StatsEntry entry;
        for (const Figure& f : figures) {
            const std::string_view field = next_field(rest);
            if (field.empty())
                return fail(std::string("missing the ") + f.name);
            std::string error;
            const auto count = parse_count(field, error);
            if (!count)
                return fail(std::string(f.name) + ": " + error);
            entry.stats.*f.field = *count;
        }
        const std::string_view name = trim(rest);
        if (name.empty())
            return fail("missing the player's name");
        if (!valid_utf8(name))
            return fail("the name is not valid UTF-8");
        if (stats_name(name) != name)
            return fail("control characters in the name");
        if (const auto problem = contradiction(entry.stats))
            return fail(*problem);
        if (const StatsEntry* twice = store.find(name))
            return fail(
                "'" + std::string(name) + "' is listed twice (first at line " +
                std::to_string(first_line[static_cast<std::size_t>(twice - store.players.data())]) +
                ")");
        entry.name = std::string(name);
        store.players.push_back(std::move(entry));
        first_line.push_back(line.number);
    }
    if (!have_header)
        return StatsError{std::max(last_line, 1),
                          "no '" + header() + "' line: not a stats file, or cut short"};
    return store;
}

void add_game(StatsStore& store, const std::string names[2], const PlayerStats stats[2]) {
    for (int p = 0; p < 2; ++p) {
        const std::string name = stats_name(names[p]);
        auto it = std::ranges::find(store.players, name, &StatsEntry::name);
        if (it == store.players.end()) {
            store.players.push_back({name, {}});
            it = store.players.end() - 1;
        }
        it->stats.add(stats[p]);
    }
}

bool remove_player(StatsStore& store, std::string_view name) {
    const auto it = std::ranges::find(store.players, name, &StatsEntry::name);
    if (it == store.players.end())
        return false;
    store.players.erase(it);
    return true;
}

std::string stats_path() {
    return xdg_dir("XDG_STATE_HOME", ".local/state") + "/termpool/stats";
}

StatsFile read_stats_file(const std::string& path) {
    StatsFile file;
    std::string error;
    const std::optional<std::string> text = read_whole_file(path, error);
    if (!text) {
        file.state = error.empty() ? StatsFile::State::missing : StatsFile::State::unreadable;
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
    fd_ = ::open((path + ".lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600);
    if (fd_ < 0)
        return;
    while (::flock(fd_, LOCK_EX) != 0 && errno == EINTR) {
    }
}

StatsLock::~StatsLock() {
    if (fd_ >= 0)
        ::close(fd_); // releases the lock
}

std::string save_game_stats(const std::string& path, const std::string names[2],
                            const PlayerStats stats[2]) {
    const StatsLock lock(path);
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
    add_game(file.store, names, stats);
    std::string error;
    if (!write_atomically(path, format_stats(file.store), error))
        return (notice.empty() ? "" : notice + "; ") + "could not save the statistics: " + error;
    return notice;
}

} // namespace termpool
