#include "tui/game_main.hpp"

#include <cstdio>
#include <stdexcept>

#include "tui/app.hpp"
#include "tui/config.hpp"
#include "tui/options.hpp"
#include "tui/save_file.hpp"

#include "tui/terminal.hpp"
#include <termpool/record.hpp>

namespace termpool::tui {

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
    std::optional<GameRecord> record;
    std::optional<Game> resumed;
    std::string notice;
    if (saved) {
        auto parsed = parse_record(*saved);
        std::optional<RecordError> problem;
        if (auto* e = std::get_if<RecordError>(&parsed)) {
            problem = *e;
        } else {
            auto replayed = replay_record(std::get<GameRecord>(parsed));
            if (auto* e2 = std::get_if<RecordError>(&replayed))
                problem = *e2;
            else if (options->resume) {
                record = std::get<GameRecord>(parsed);
                resumed.emplace(std::move(std::get<Game>(replayed)));
            }
        }
        if (problem) {
            std::fprintf(stderr, "%s:%d: %s\n", path.c_str(), problem->line,
                         problem->message.c_str());
            std::rename(path.c_str(), (path + ".bad").c_str());
            if (options->resume) {
                std::fprintf(stderr, "termpool: kept it as %s.bad\n", path.c_str());
                return 2;
            }
            notice = "The old save could not be read; it is kept as " + path + ".bad";
        }
    } else if (options->resume) {
        std::fprintf(stderr, "termpool: no saved game to resume (%s)\n",
                     read_error.empty() ? path.c_str() : read_error.c_str());
        return 1;
    }

    GameOptions chosen = *options;
    if (record) {
        chosen.game = record->game;
        chosen.table = record->table;
        chosen.friction = record->friction;
        chosen.cue_ball_mass = record->cue_ball_mass;
        chosen.names[0] = record->names[0];
        chosen.names[1] = record->names[1];
        chosen.watch.reset();
        chosen.computer.reset();
    }
    int signal = 0;
    try {
        Terminal terminal(options->ascii, options->ascii);
        App app(terminal, chosen);
        if (record)
            app.resume(*record, std::move(*resumed));
        else if (!notice.empty())
            app.tell(notice);
        app.run();
        signal = Terminal::signal_number();
    } catch (const std::exception& e) {
        restore_terminal_modes();
        std::fprintf(stderr, "termpool: %s\n", e.what());
        return 1;
    }
    // Leave as a signal would, now that the terminal is restored.
    return signal != 0 ? 128 + signal : 0;
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
    auto parsed = parse_record(*text);
    std::optional<RecordError> problem;
    if (auto* e = std::get_if<RecordError>(&parsed)) {
        problem = *e;
    } else if (auto replayed = replay_record(std::get<GameRecord>(parsed));
               std::holds_alternative<RecordError>(replayed)) {
        problem = std::get<RecordError>(replayed);
    }
    if (problem) {
        std::fprintf(stderr, "%s:%d: %s\n", path.c_str(), problem->line, problem->message.c_str());
        return 2;
    }
    const GameRecord& record = std::get<GameRecord>(parsed);
    GameOptions options;
    options.game = record.game;
    options.table = record.table;
    options.friction = record.friction;
    options.cue_ball_mass = record.cue_ball_mass;
    options.names[0] = record.names[0];
    options.names[1] = record.names[1];
    int signal = 0;
    try {
        Terminal terminal(false, false);
        App app(terminal, options);
        app.start_replay(record);
        app.run();
        signal = Terminal::signal_number();
    } catch (const std::exception& e) {
        restore_terminal_modes();
        std::fprintf(stderr, "termpool: %s\n", e.what());
        return 1;
    }
    return signal != 0 ? 128 + signal : 0;
}

} // namespace termpool::tui
