// `termpool simulate [FILE]`: reads a scenario, simulates the shot, prints events and the end,
// and with a game context what the referee made of the shot.

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <termpool/rules.hpp>
#include <termpool/simulator.hpp>
#include <unistd.h>
#include <variant>

#include "cli/commands.hpp"
#include "cli/scenario.hpp"
#include "cli/shot_output.hpp"
#include "files/file_limits.hpp"
#include "files/read_file.hpp"

namespace termpool::cli {
namespace {

constexpr const char* usage =
    "usage: termpool simulate [FILE]   (FILE '-' or none: standard input)\n";

/// What reading the input gave: its text, or why there is none.
struct Input {
    bool ok = false;
    std::string text;  ///< the whole input when ok
    std::string error; ///< the message otherwise, after "termpool: "
};

/// Reads all of `path` (shown as `name`), or of standard input for "-", at most
/// max_scenario_bytes: a scenario is a screenful, and a file or pipe that goes on and on is
/// refused, not read.
Input read_input(const std::string& path, const std::string& name) {
    const bool from_stdin = path == "-";
    const int fd = from_stdin ? STDIN_FILENO : ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return {false, {}, "cannot read " + name + ": " + std::strerror(errno)};
    Input input;
    if (auto text = read_bounded(fd, name, max_scenario_bytes, input.error)) {
        input.ok = true;
        input.text = std::move(*text);
    }
    if (!from_stdin)
        ::close(fd);
    return input;
}

} // namespace

int simulate_command(const std::vector<std::string>& args) {
    if (args.size() == 1 && (args[0] == "-h" || args[0] == "--help")) {
        std::fputs(usage, stdout);
        return 0;
    }
    if (args.size() > 1 || (args.size() == 1 && args[0].size() > 1 && args[0][0] == '-')) {
        std::fputs(usage, stderr);
        return 2;
    }
    const std::string path = args.empty() ? "-" : args[0];
    const std::string name = path == "-" ? "<stdin>" : path;

    const Input input = read_input(path, name);
    if (!input.ok) {
        std::fprintf(stderr, "termpool: %s\n", input.error.c_str());
        return 2;
    }
    // Everything is parsed and checked before the first byte of output.
    const ScenarioResult parsed = parse_scenario(input.text);
    if (const auto* error = std::get_if<ScenarioError>(&parsed)) {
        std::fprintf(stderr, "%s:%d: %s\n", name.c_str(), error->line, error->message.c_str());
        return 2;
    }
    const Scenario& scenario = std::get<Scenario>(parsed);

    std::string output;
    bool cut_short = false;
    if (scenario.strike) {
        const ShotResult shot =
            simulate_shot(scenario.table, scenario.setup.physics, scenario.balls, *scenario.strike);
        output = format_shot(shot.events, shot.balls, shot.rest_time);
        cut_short = shot.event_limit_hit;
        // A shot stopped before the balls came to rest has no outcome to judge yet.
        if (scenario.game && !cut_short) {
            const GameContext& context = *scenario.game;
            Game game = Game::from_position(
                scenario.setup.game, scenario.table, scenario.setup.physics, scenario.balls,
                context.shooter, context.player1_group, context.is_break, context.push_out);
            output += format_verdict(game.apply(ShotCall{context.call, context.push_out}, shot));
        }
    } else {
        output = format_shot({}, scenario.balls, 0);
    }

    std::fwrite(output.data(), 1, output.size(), stdout);
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
        std::fprintf(stderr, "termpool: cannot write the output: %s\n", std::strerror(errno));
        return 1;
    }
    if (cut_short) {
        std::fprintf(stderr,
                     "termpool: warning: %s: the shot was stopped after %zu events, before every "
                     "ball came to rest\n",
                     name.c_str(), World::max_events);
        return 1;
    }
    return 0;
}

} // namespace termpool::cli
