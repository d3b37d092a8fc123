// termpool entry point: dispatches to the subcommands.

#include "cli/commands.hpp"
#include "cli/saves_command.hpp"
#include "cli/stats_command.hpp"
#include "hall/hall_main.hpp"
#include "tui/bench_render.hpp"
#include "tui/game_main.hpp"
#include "tui/hall_session.hpp"
#include <termpool/version.hpp>

#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace {

void print_usage(std::ostream& out) {
    out << "usage: termpool [OPTIONS]            play pool in the terminal\n"
           "       termpool COMMAND [ARGS...]\n"
           "\n"
           "options of the game:\n"
        << termpool::tui::game_options_usage()
        << "  --version             print the version and exit\n"
           "\n"
           "commands:\n"
           "  practice [--game G]   practise alone at the table\n"
           "  stats [--reset NAME]  the players' totals over their finished games\n"
           "  saves [--remove N]    the saved games to continue, newest first; remove one\n"
           "  replay [FILE]         play a saved game back (default: the game saved last)\n"
           "  simulate [FILE]       run the physics simulator on a scenario (standard input\n"
           "                        if FILE is omitted or -)\n"
           "  bench [--breaks N] [--shots N] [--seed S]\n"
           "                        time the simulator on one core\n"
           "  bench --render        time the terminal front end: frames and bytes sent\n"
           "  experiment friction [--table T] [--csv] | mass [--csv]\n"
           "                        the seed report's friction and mass study\n"
           "  experiment throw [--model fit|constant] [--csv]\n"
           "                        throw against cut angle at several speeds\n"
           "  selfplay --games N --p1 LEVEL --p2 LEVEL [--game G] [--seed S] [--jobs J]\n"
           "                        computer against computer\n"
           "  hall [--name NAME] [--socket PATH] [--ascii]\n"
           "                        play in the pool hall (its server starts if need be)\n"
           "  hall serve [--socket PATH] [--state DIR] [--max-clients N] [--max-tables N]\n"
           "             [--idle-exit S]\n"
           "                        run the pool hall's server (friends play over SSH)\n"
           "  hall bench [--tables N] [--seconds S] [--think MS] [--seed S]\n"
           "                        time the hall: tables of computers through its server\n"
           "  COMMAND --help        the options of one command\n";
}

} // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);

    // No command, or only the game's options: play.
    if (args.empty() ||
        (args.front().starts_with("--") && args.front() != "--help" && args.front() != "--version"))
        return termpool::tui::run_game(args);

    const std::string& command = args.front();
    const std::vector<std::string> rest(args.begin() + 1, args.end());

    if (command == "--help" || command == "-h") {
        print_usage(std::cout);
        return 0;
    }
    if (command == "--version") {
        std::cout << "termpool " << TERMPOOL_VERSION << '\n';
        return 0;
    }

    try {
        if (command == "simulate") {
            return termpool::cli::simulate_command(rest);
        }
        if (command == "bench") {
            // The commands do not include the front end: --render's figures come from here.
            return termpool::cli::bench_command(rest, termpool::tui::bench_render);
        }
        if (command == "practice") {
            return termpool::tui::run_practice(rest);
        }
        if (command == "replay") {
            return termpool::tui::run_replay(rest);
        }
        if (command == "experiment") {
            return termpool::cli::experiment_command(rest);
        }
        if (command == "selfplay") {
            return termpool::cli::selfplay_command(rest);
        }
        if (command == "hall") {
            // serve and bench are the hall's own; the rest is a player's terminal in it.
            if (!rest.empty() &&
                (rest.front() == "serve" || rest.front() == "bench" || rest.front() == "who"))
                return termpool::hall::hall_command(rest);
            return termpool::tui::run_hall(rest);
        }
        if (command == "stats") {
            return termpool::cli::stats_command(rest);
        }
        if (command == "saves") {
            return termpool::cli::saves_command(rest);
        }
    } catch (const std::exception& e) {
        std::cerr << "termpool: error: " << e.what() << '\n';
        return 1;
    }

    std::cerr << "termpool: unknown " << (command.starts_with('-') ? "option" : "command") << " '"
              << command << "'\n\n";
    print_usage(std::cerr);
    return 2;
}
