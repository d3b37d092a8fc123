#include "tui/game_main.hpp"

#include <cstdio>
#include <functional>
#include <stdexcept>
#include <variant>

#include "tui/app.hpp"
#include "tui/config.hpp"
#include "tui/options.hpp"
#include "tui/save_file.hpp"

#include "tui/terminal.hpp"
#include <termpool/record.hpp>

namespace termpool::tui {
namespace {

// A saved game, read and replayed to where it stands.
struct LoadedGame {
    GameRecord record;
    Game game;
};

std::variant<LoadedGame, RecordError> load_game(const std::string& text) {
    auto parsed = parse_record(text);
    if (auto* problem = std::get_if<RecordError>(&parsed))
        return *problem;
    GameRecord& record = std::get<GameRecord>(parsed);
    auto replayed = replay_record(record);
    if (auto* problem = std::get_if<RecordError>(&replayed))
        return *problem;
    return LoadedGame{std::move(record), std::move(std::get<Game>(replayed))};
}

// The options a record was played with; how it is shown (ASCII, colour) stays as given.
GameOptions options_from(const GameRecord& record, GameOptions options) {
    options.game = record.game;
    options.table = record.table;
    options.friction = record.friction;
    options.cue_ball_mass = record.cue_ball_mass;
    options.race_to = record.race_to;
    options.break_rule = record.break_rule;
    options.names[0] = record.names[0];
    options.names[1] = record.names[1];
    options.watch.reset();
    options.computer.reset();
    return options;
}

// Runs the game in the terminal after `setup` has prepared it. The exit status is 1 without a
// usable terminal, and what a signal would give after one ended the game.
int in_terminal(const GameOptions& options, const std::function<void(App&)>& setup) {
    int signal = 0;
    try {
        Terminal terminal(options.ascii, options.ascii);
        App app(terminal, options);
        setup(app);
        app.run();
        signal = Terminal::signal_number();
    } catch (const std::exception& e) {
        restore_terminal_modes();
        std::fprintf(stderr, "termpool: %s\n", e.what());
        return 1;
    }
    return signal != 0 ? 128 + signal : 0;
}

} // namespace

int run_game(const std::vector<std::string>& args) {
    // The config file's defaults first; the command line overrides them.
    GameOptions defaults;
    std::string config_error;
    if (const auto config = read_whole_file(config_path(), config_error)) {
        std::vector<std::string> warnings;
        if (const auto bad = apply_config(*config, defaults, warnings)) {
            std::fprintf(stderr, "%s:%s\n", config_path().c_str(), bad->c_str());
            return 2;
        }
        for (const std::string& w : warnings)
            std::fprintf(stderr, "termpool: warning: %s\n", w.c_str());
    }
    std::string error;
    const auto options = parse_game_options(args, error, defaults);
    if (!options) {
        std::fprintf(stderr,
                     "termpool: %s\nusage: termpool [--player1 NAME] [--player2 NAME] "
                     "[--game 8ball|8ball-bar|9ball] [--table 7ft|8ft|9ft] [--ascii]\n"
                     "               [--vs-computer [LEVEL]] [--watch [LEVEL]]   (LEVEL: easy, "
                     "medium, hard, pro)\n",
                     error.c_str());
        return 2;
    }
    // A save that cannot be read is never overwritten: it is kept beside as NAME.bad.
    const std::string path = save_path();
    std::string read_error;
    const std::optional<std::string> saved = read_whole_file(path, read_error);
    std::optional<LoadedGame> loaded;
    std::string notice;
    if (saved) {
        auto result = load_game(*saved);
        if (auto* problem = std::get_if<RecordError>(&result)) {
            std::fprintf(stderr, "%s:%d: %s\n", path.c_str(), problem->line,
                         problem->message.c_str());
            std::rename(path.c_str(), (path + ".bad").c_str());
            if (options->resume) {
                std::fprintf(stderr, "termpool: kept it as %s.bad\n", path.c_str());
                return 2;
            }
            notice = "The old save could not be read; it is kept as " + path + ".bad";
        } else if (options->resume) {
            loaded.emplace(std::move(std::get<LoadedGame>(result)));
        }
    } else if (options->resume) {
        std::fprintf(stderr, "termpool: no saved game to resume (%s)\n",
                     read_error.empty() ? path.c_str() : read_error.c_str());
        return 1;
    }

    if (loaded)
        return in_terminal(options_from(loaded->record, *options),
                           [&](App& app) { app.resume(loaded->record); });
    return in_terminal(*options, [&](App& app) {
        if (!notice.empty())
            app.tell(notice);
    });
}

int run_practice(const std::vector<std::string>& args) {
    GameOptions defaults;
    std::string config_error;
    if (const auto config = read_whole_file(config_path(), config_error)) {
        std::vector<std::string> warnings;
        if (const auto bad = apply_config(*config, defaults, warnings)) {
            std::fprintf(stderr, "%s:%s\n", config_path().c_str(), bad->c_str());
            return 2;
        }
    }
    std::string error;
    auto options = parse_game_options(args, error, defaults);
    if (options && (options->resume || options->watch || options->computer))
        error = "practice is one player at the table: no --resume, --vs-computer or --watch";
    if (!options || !error.empty()) {
        std::fprintf(stderr,
                     "termpool: %s\nusage: termpool practice [--game 8ball|8ball-bar|9ball] "
                     "[--table 7ft|8ft|9ft] [--player1 NAME] [--seed S] [--ascii]\n",
                     error.c_str());
        return 2;
    }
    options->practice = true;
    return in_terminal(*options, [](App&) {});
}

int run_replay(const std::vector<std::string>& args) {
    if (args.size() != 1) {
        std::fprintf(stderr, "usage: termpool replay FILE\n");
        return 2;
    }
    const std::string& path = args[0];
    std::string error;
    const std::optional<std::string> text = read_whole_file(path, error);
    if (!text) {
        std::fprintf(stderr, "termpool: cannot read %s\n",
                     error.empty() ? (path + ": no such file").c_str() : error.c_str());
        return 2;
    }
    auto result = load_game(*text);
    if (auto* problem = std::get_if<RecordError>(&result)) {
        std::fprintf(stderr, "%s:%d: %s\n", path.c_str(), problem->line, problem->message.c_str());
        return 2;
    }
    const GameRecord& record = std::get<LoadedGame>(result).record;
    return in_terminal(options_from(record, GameOptions{}),
                       [&](App& app) { app.start_replay(record); });
}

} // namespace termpool::tui
