#include "cli/stats_command.hpp"

#include <cstdio>

#include "player/save_file.hpp"
#include "player/stats_figures.hpp"
#include <termpool/text_width.hpp>

namespace termpool::cli {
namespace {

constexpr const char* usage = "usage: termpool stats [--reset NAME] [--help]\n";

constexpr const char* help = "usage: termpool stats [--reset NAME] [--help]\n"
                             "\n"
                             "Prints every player's totals over all finished games, a section\n"
                             "per game type (pool racks and snooker frames apart), from\n"
                             "$XDG_STATE_HOME/termpool/stats (~/.local/state/termpool/stats).\n"
                             "\n"
                             "  --reset NAME   forget the totals of the player NAME\n"
                             "  -h, --help     print this help and exit\n";

std::string padded(const std::string& s, int columns, bool left) {
    const std::string pad(static_cast<std::size_t>(std::max(0, columns - display_width(s))), ' ');
    return left ? s + pad : pad + s;
}

int reset(const std::string& path, const std::string& name) {
    const StatsLock lock(path);
    StatsFile file = read_stats_file(path);
    switch (file.state) {
    case StatsFile::State::missing:
        std::fprintf(stderr, "termpool: no statistics yet (%s)\n", path.c_str());
        return 1;
    case StatsFile::State::unreadable:
        std::fprintf(stderr, "termpool: %s\n", file.problem.c_str());
        return 1;
    case StatsFile::State::damaged:
        std::fprintf(stderr, "%s\n", file.problem.c_str());
        return 2;
    case StatsFile::State::read:
        break;
    }
    if (!remove_player(file.store, stats_name(name))) {
        std::fprintf(stderr, "termpool: no statistics for '%s' in %s\n", stats_name(name).c_str(),
                     path.c_str());
        return 1;
    }
    std::string error;
    if (!write_atomically(path, format_stats(file.store), error)) {
        std::fprintf(stderr, "termpool: %s\n", error.c_str());
        return 1;
    }
    std::printf("Forgot the statistics of %s.\n", stats_name(name).c_str());
    return 0;
}

} // namespace

std::string stats_table(const StatsStore& store) {
    std::vector<StatsGame> games;
    for (const GameType game : stats_game_order())
        games.push_back(game);
    games.push_back(std::nullopt); // a version 1 file's totals of all games, last
    std::string text;
    bool kind_shown[2] = {false, false};
    for (const StatsGame& game : games) {
        const StatsKind kind = stats_kind_of(game);
        const StatsFigures& figures = stats_figures(kind);
        std::vector<std::vector<std::string>> rows = {{"Player"}};
        for (const StatsColumn& column : figures.table)
            rows[0].push_back(column.header);
        for (const StatsEntry& e : store.players) {
            if (e.game != game)
                continue;
            rows.push_back({e.name});
            for (const StatsColumn& column : figures.table)
                rows.back().push_back(column.figure(e.stats));
        }
        if (rows.size() == 1)
            continue;
        kind_shown[static_cast<int>(kind)] = true;
        std::vector<int> widths(rows[0].size(), 0);
        for (const auto& row : rows)
            for (std::size_t c = 0; c < row.size(); ++c)
                widths[c] = std::max(widths[c], display_width(row[c]));
        text += stats_game_title(game) + "\n";
        for (const auto& row : rows) {
            std::string line;
            for (std::size_t c = 0; c < row.size(); ++c)
                line += (c == 0 ? "" : "  ") + padded(row[c], widths[c], c == 0);
            text += line + "\n";
        }
        text += "\n";
    }
    // One legend per kind shown, a blank line between them.
    std::string legends;
    for (const StatsKind kind : {StatsKind::pool, StatsKind::snooker})
        if (kind_shown[static_cast<int>(kind)])
            legends += (legends.empty() ? "" : "\n") + std::string(stats_figures(kind).legend);
    return text + legends;
}

int stats_command(const std::vector<std::string>& args) {
    std::optional<std::string> reset_name;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--help" || args[i] == "-h") {
            std::fputs(help, stdout);
            return 0;
        }
        if (args[i] == "--reset" && i + 1 < args.size() && !reset_name) {
            reset_name = args[++i];
            continue;
        }
        std::fprintf(stderr, "termpool stats: %s '%s'\n%s",
                     args[i] == "--reset" ? "--reset needs one NAME, not" : "unknown argument",
                     args[i].c_str(), usage);
        return 2;
    }
    const std::string path = stats_path();
    if (reset_name)
        return reset(path, *reset_name);

    const StatsFile file = read_stats_file(path);
    switch (file.state) {
    case StatsFile::State::missing:
        std::printf("No statistics yet: they are kept in %s after each finished game.\n",
                    path.c_str());
        return 0;
    case StatsFile::State::unreadable:
        std::fprintf(stderr, "termpool: %s\n", file.problem.c_str());
        return 1;
    case StatsFile::State::damaged:
        std::fprintf(stderr,
                     "%s\ntermpool: the file is left as it is; the next finished game moves it "
                     "aside (.bad) and starts new totals\n",
                     file.problem.c_str());
        return 2;
    case StatsFile::State::read:
        break;
    }
    if (file.store.players.empty()) {
        std::printf("No statistics yet: %s lists no players.\n", path.c_str());
        return 0;
    }
    std::fputs(stats_table(file.store).c_str(), stdout);
    return 0;
}

} // namespace termpool::cli
