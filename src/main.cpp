// termpool entry point: dispatches to the subcommands.

#include "cli/commands.hpp"

#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace {

constexpr const char* kVersion = "0.1.0";

void print_usage(std::ostream& out) {
    out << "usage: termpool [COMMAND] [ARGS...]\n"
           "\n"
           "commands:\n"
           "  termpool                     play pool in the terminal (coming soon)\n"
           "  termpool simulate [FILE]     run the physics simulator on FILE\n"
           "                               (standard input if FILE is omitted or -)\n"
           "  termpool bench [--breaks N] [--shots N] [--seed S]\n"
           "                               time the simulator on one core\n"
           "\n"
           "options:\n"
           "  -h, --help                   print this help and exit\n"
           "  --version                    print the version and exit\n";
}

} // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);

    if (args.empty()) {
        std::cerr << "termpool: the terminal game is not built yet in this version.\n"
                     "See 'termpool --help' for the available commands.\n";
        return 1;
    }

    const std::string& command = args.front();
    const std::vector<std::string> rest(args.begin() + 1, args.end());

    if (command == "--help" || command == "-h") {
        print_usage(std::cout);
        return 0;
    }
    if (command == "--version") {
        std::cout << "termpool " << kVersion << '\n';
        return 0;
    }

    try {
        if (command == "simulate") {
            return termpool::cli::simulate_command(rest);
        }
        if (command == "bench") {
            return termpool::cli::bench_command(rest);
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
