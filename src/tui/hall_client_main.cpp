// `termpool hall [--name NAME] [--socket PATH] [--ascii]`: the command line read, the
// terminal started, the session run.

#include <cstdio>
#include <exception>

#include "hall/autostart.hpp"
#include "hall/hall_main.hpp"
#include "hall/socket_dir.hpp"
#include "hall/socket_trust.hpp"
#include "hall/token_store.hpp"
#include "player/player_name.hpp"
#include "tui/hall_session.hpp"

namespace termpool::tui {
namespace {

constexpr const char* usage =
    "usage: termpool hall [--name NAME] [--socket PATH] [--ascii]\n"
    "  play in the pool hall: the lobby's tables, friends in their own terminals\n"
    "  --name NAME    your name in the hall (asked for when not given)\n"
    "  --socket PATH  the hall's socket (default $XDG_RUNTIME_DIR/termpool/hall.sock, or\n"
    "                 /tmp/termpool-UID/hall.sock); a hall that is not running is started\n"
    "  --ascii        plain ASCII, no colour\n";

} // namespace

int run_hall(const std::vector<std::string>& args) {
    HallOptions options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "--help" || arg == "-h") {
            std::fputs(usage, stdout);
            std::fputs(hall::hall_usage(), stdout);
            return 0;
        }
        if (arg == "--ascii") {
            options.ascii = true;
            continue;
        }
        if ((arg == "--name" || arg == "--socket") && i + 1 < args.size()) {
            const std::string& value = args[++i];
            if (arg == "--socket") {
                options.socket_path = value;
                continue;
            }
            std::string error;
            const auto name = clean_player_name(value, error);
            if (!name) {
                // The reason alone, on one line: under an SSH forced command the usage would
                // push it off the screen.
                std::fprintf(stderr, "termpool hall: --name: %s (termpool hall --help: usage)\n",
                             error.empty() ? "the name is blank" : error.c_str());
                return 2;
            }
            options.name = *name;
            continue;
        }
        std::fprintf(stderr, "termpool hall: %s\n\n%s%s",
                     arg == "--name" || arg == "--socket"
                         ? (arg + " needs a value").c_str()
                         : ("unknown argument '" + arg + "'").c_str(),
                     usage, hall::hall_usage());
        return 2;
    }
    if (options.socket_path.empty())
        options.socket_path = hall::default_socket_path();
    options.self_exe = hall::own_executable();
    if (options.self_exe.empty())
        options.self_exe = "termpool"; // from PATH
    options.token_dir = hall::default_token_dir();
    // A hall another user planted is refused before the screen is taken or a name asked; one
    // found later ends the session, and is said once the terminal is given back.
    if (const std::string problem = hall::check_socket_path(options.socket_path);
        !problem.empty()) {
        std::fprintf(stderr, "termpool hall: %s\n", problem.c_str());
        return 1;
    }
    try {
        std::string refusal;
        {
            Terminal terminal(options.ascii, options.ascii);
            HallSession session(terminal, options);
            session.run();
            refusal = session.refusal();
        }
        if (!refusal.empty()) {
            std::fprintf(stderr, "termpool hall: %s\n", refusal.c_str());
            return 1;
        }
        const int signal = Terminal::signal_number();
        return signal != 0 ? 128 + signal : 0;
    } catch (const std::exception& e) {
        restore_terminal_modes();
        std::fprintf(stderr, "termpool hall: %s\n", e.what());
        return 1;
    }
}

} // namespace termpool::tui
