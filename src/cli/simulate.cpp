// `termpool simulate [FILE]`: reads a scenario, simulates the shot, prints events and the end,
// and with a game context what the referee made of the shot.

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <termpool/rules.hpp>
#include <termpool/simulator.hpp>
#include <variant>

#include "cli/commands.hpp"
#include "cli/scenario.hpp"
#include "cli/shot_output.hpp"

namespace termpool::cli {
namespace {

constexpr const char* usage =
    "usage: termpool simulate [FILE]   (FILE '-' or none: standard input)\n";

/// What reading the input gave: its text, or why there is none.
struct Input {
    bool ok = false;
    std::string text;  ///< the whole input when ok
    std::string error; ///< strerror of the failure otherwise
};

/// Reads all of `path`, or of standard input for "-".
Input read_input(const std::string& path) {
    const bool from_stdin = path == "-";
    std::FILE* file = from_stdin ? stdin : std::fopen(path.c_str(), "rb");
    if (!file)
        return {false, {}, std::strerror(errno)};
    Input input{true, {}, {}};
    char buffer[65536];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0)
        input.text.append(buffer, n);
    // errno means something only right after the failing call, so take it before fclose.
    const int error = std::ferror(file) ? errno : 0;
    if (!from_stdin)
        std::fclose(file);
    if (error != 0)
        return {false, {}, std::strerror(error)};
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

    const Input input = read_input(path);
    if (!input.ok) {
        std::fprintf(stderr, "termpool: cannot read %s: %s\n", name.c_str(), input.error.c_str());
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
