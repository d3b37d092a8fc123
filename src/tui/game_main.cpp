#include "tui/game_main.hpp"

#include <cstdio>
#include <stdexcept>

#include "tui/app.hpp"
#include "tui/options.hpp"
#include "tui/terminal.hpp"

namespace termpool::tui {

int run_game(const std::vector<std::string>& args) {
    std::string error;
    const auto options = parse_game_options(args, error);
    if (!options) {
        std::fprintf(stderr,
                     "termpool: %s\nusage: termpool [--player1 NAME] [--player2 NAME] "
                     "[--game 8ball|8ball-bar|9ball] [--table 7ft|8ft|9ft] [--ascii]\n"
                     "               [--vs-computer [LEVEL]] [--watch [LEVEL]]   (LEVEL: easy, "
                     "medium, hard, pro)\n",
                     error.c_str());
        return 2;
    }
    int signal = 0;
    try {
        Terminal terminal(options->ascii, options->ascii);
        App app(terminal, *options);
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

} // namespace termpool::tui
