#include "tui/game_main.hpp"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <functional>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>
#include <variant>

#include "files/file_limits.hpp"
#include "files/keep_aside.hpp"
#include "files/read_file.hpp"
#include "files/self_command.hpp"
#include "player/config.hpp"
#include "player/options.hpp"
#include "player/save_file.hpp"
#include "player/save_list.hpp"
#include "player/save_read.hpp"
#include "player/save_slots.hpp"
#include "player/save_summary.hpp"
#include "tui/app.hpp"
#include "tui/save_prompt.hpp"

#include "tui/terminal.hpp"
#include <termpool/record.hpp>
#include <termpool/stats.hpp>

namespace termpool::tui {
namespace {

constexpr const char* options_usage =
    "  --player1 NAME, --player2 NAME\n"
    "                        the players' names (asked for when not given)\n"
    "  --game 8ball|8ball-bar|9ball|10ball|snooker\n"
    "                        the game (default 8ball; snooker is played on the snooker\n"
    "                        table)\n"
    "  --table 7ft|8ft|9ft|snooker\n                        the table (default 9ft; snooker: 12 "
    "ft, snooker balls)\n"
    "  --race N              a match: the first to win N racks (1 to 99; default 1, or\n"
    "                        asked at the end of the name prompt)\n"
    "  --best-of N           snooker's way of saying it: a match of N frames, N odd (1 to\n"
    "                        197), won by the first to win more than half\n"
    "  --breaks alternate|winner\n"
    "                        who breaks each next rack of a match (default alternate)\n"
    "  --seed S              the first rack's seed, to set a game up again exactly\n"
    "  --assist guided|standard|pro\n"
    "                        how much the aiming aid helps (default standard): guided\n"
    "                        opens at the easiest pot and draws the shot to the rails,\n"
    "                        standard opens full on a legal ball, pro draws the cue\n"
    "                        ball's line to its first contact only\n"
    "  --vs-computer [LEVEL] the computer is player 2; LEVEL is easy, medium, hard or pro\n"
    "                        (default medium, or the config file's level)\n"
    "  --watch [LEVEL]       the computer plays both sides\n"
    "  --friction physical | decay K | constant A | combined K A\n"
    "                        the cloth model (default physical)\n"
    "  --cue-ball-mass KG    the cue ball's mass, 0.05 to 1 (default: as the others)\n"
    "  --cue standard|low-deflection|none\n"
    "                        the cue's shaft: how much side spin squirts the cue ball\n"
    "                        (default standard; none: no squirt)\n"
    "  --ascii               plain ASCII, no colour\n"
    "  --resume [N | FILE]   continue an unfinished game: the only one, save N (1 is\n"
    "                        game.save, N is game-N.save) or FILE; with several, pick one\n"
    "                        from the list, newest first (d N removes save N)\n"
    "  -h, --help            print this help and exit\n"
    "Defaults come from $XDG_CONFIG_HOME/termpool/config (~/.config/termpool/config);\n"
    "games are saved in $XDG_STATE_HOME/termpool/ (~/.local/state/termpool/).\n";

void print_game_usage(std::FILE* out) {
    std::fprintf(out, "usage: termpool [OPTIONS]   (commands: termpool --help)\n%s", options_usage);
}

// Where a slot's save that is not a game went, in words: it is moved aside, never over an
// older one, and never overwritten.
std::string keep_bad_save(const std::string& path) {
    std::string why;
    if (const auto kept = keep_aside(path, why))
        return "it is kept as " + *kept;
    return "it could not be moved aside (" + why + ")";
}

// Says on stderr why the save at `path` is not a game; a slot's is moved aside.
void report_bad_save(const std::string& path, const RecordError& problem) {
    std::fprintf(stderr, "%s:%d: %s\n", path.c_str(), problem.line, problem.message.c_str());
    if (slot_of(path) != 0)
        std::fprintf(stderr, "termpool: %s\n", keep_bad_save(path).c_str());
}

// The options a record was played with; how it is shown (ASCII, colour) stays as given.
GameOptions options_from(const GameRecord& record, GameOptions options) {
    options.setup = record.setup;
    options.race_to = record.race_to;
    options.break_rule = record.break_rule;
    options.names[0] = record.names[0];
    options.names[1] = record.names[1];
    options.watch.reset();
    options.computer.reset();
    options.assist = record.assist; // a game keeps its assist, for both seats
    return options;
}

// Runs the game in the terminal after `setup` has prepared it. The exit status is 1 without a
// usable terminal, and what a signal would give after one ended the game (a terminal that
// hung up counts as SIGHUP).
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

// How to continue the save at `path`: plain --resume while it is the only save.
std::string resume_command(const std::string& path) {
    const int slot = slot_of(path);
    const std::string resume = self_command() + " --resume";
    if (slot == 0)
        return resume + " " + path;
    const std::vector<int> slots = existing_slots();
    if (slots.size() == 1 && slots.front() == slot)
        return resume;
    return resume + " " + std::to_string(slot);
}

// After curses has ended: where the game is and how to go on with it, when there is a game.
void tell_where_saved(const std::string& path, const std::optional<std::string>& before,
                      bool resumed) {
    const SaveContents after = read_save(path);
    if (!after.text || (!resumed && after.text == before))
        return; // nothing was played (the names were never entered)
    // A game that is over has nothing to continue: it can be watched again.
    if (after.game && finished(*after.game)) {
        // The next new game takes the slot of a finished one: say so, or the advice goes stale.
        std::printf("Game over, saved in %s until a new game takes its place; watch it again "
                    "with: %s replay %s\n",
                    display_path(path).c_str(), self_command().c_str(), display_path(path).c_str());
        return;
    }
    std::printf("Game saved in %s; continue it with: %s\n", display_path(path).c_str(),
                resume_command(path).c_str());
}

// A save chosen to go on with, locked for as long as the game runs.
struct Chosen {
    SaveLock lock;
    Match game;
};

// The unfinished save `save` to go on with, its lock kept.
Chosen continue_with(SlotSave& save) {
    return Chosen{std::move(save.lock), std::move(*save.contents.game)};
}

// `--resume N` or `--resume FILE`: that save, or the exit status after saying why not. A
// finished game is not continued by number (the lists never offer it); a FILE named is
// opened whatever it holds.
std::variant<Chosen, int> resume_named(const std::string& which) {
    // Digits name a save by its number (too many digits name none); anything else is a file.
    const bool number =
        std::all_of(which.begin(), which.end(), [](char c) { return c >= '0' && c <= '9'; });
    const int slot = parse_slot_number(which);
    if (number && (slot < 1 || slot_of(slot_path(slot)) != slot)) {
        std::fprintf(stderr, "termpool: there is no save %s (%s --resume lists them)\n",
                     which.c_str(), self_command().c_str());
        return 2;
    }
    const std::string path = number ? slot_path(slot) : which;
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        std::fprintf(stderr, "termpool: no saved game to resume (%s)\n", path.c_str());
        return 1;
    }
    SaveLock lock(path);
    if (lock.state() == SaveLock::State::busy) {
        std::fprintf(stderr, "termpool: %s is in use by another termpool game\n",
                     display_path(path).c_str());
        return 1;
    }
    SaveContents read = read_save(path);
    if (read.problem) {
        report_bad_save(path, *read.problem);
        return 2;
    }
    if (!read.error.empty()) {
        std::fprintf(stderr, "termpool: %s\n", read.error.c_str()); // too large, not a file...
        return 2;
    }
    if (!read.game) {
        std::fprintf(stderr, "termpool: no saved game to resume (%s)\n", path.c_str());
        return 1;
    }
    if (number && finished(*read.game)) {
        std::fprintf(stderr,
                     "termpool: save %d is a finished game, not one to continue; watch it again "
                     "with: %s replay %s\n",
                     slot, self_command().c_str(), display_path(path).c_str());
        return 2;
    }
    return Chosen{std::move(lock), std::move(*read.game)};
}

// Plain `--resume`: the one unfinished save no other game holds, or a list of them to pick
// from (asked in a terminal, printed otherwise). Finished games are never offered.
std::variant<Chosen, int> resume_only() {
    std::vector<SlotSave> free;
    std::vector<std::string> busy;
    bool bad = false, over = false;
    for (SlotSave& save : read_slot_saves()) {
        const SaveContents& c = save.contents;
        if (save.in_use())
            busy.push_back(display_path(save.path()));
        else if (c.problem) {
            report_bad_save(save.path(), *c.problem);
            bad = true;
        } else if (!c.error.empty())
            std::fprintf(stderr, "termpool: %s\n", c.error.c_str());
        else if (c.unfinished())
            free.push_back(std::move(save));
        else
            over |= c.game.has_value();
    }
    if (free.empty()) {
        if (bad)
            return 2;
        std::string why = display_path(save_dir());
        for (const std::string& b : busy)
            why += "; " + b + " is in use by another termpool game";
        if (over)
            why += "; finished games are kept for " + self_command() + " replay";
        std::fprintf(stderr, "termpool: no saved game to resume (%s)\n", why.c_str());
        return 1;
    }
    if (free.size() == 1)
        return continue_with(free.front());
    if (!::isatty(STDIN_FILENO) || !::isatty(STDOUT_FILENO)) {
        // No one to ask: the list, and the player picks with --resume N.
        std::printf("Saved games you can continue, newest first (%s --resume N):\n",
                    self_command().c_str());
        const std::time_t now = std::time(nullptr);
        for (const SlotSave& save : free)
            std::printf("%s\n", save_line(save, now).c_str());
        return 0;
    }
    const std::optional<std::size_t> picked = pick_save(free, stdin, stdout, std::time(nullptr));
    if (!picked)
        return 0;
    return continue_with(free[*picked]);
}

int resume_game(const GameOptions& options, const std::vector<std::string>& notices) {
    auto choice = options.resume_from.empty() ? resume_only() : resume_named(options.resume_from);
    if (const int* status = std::get_if<int>(&choice))
        return *status;
    Chosen& chosen = std::get<Chosen>(choice);
    const std::string path = chosen.lock.path();
    GameOptions resumed = options_from(chosen.game.record(), options);
    resumed.save_path = path;
    resumed.notices = notices;
    // Said when the command line or the config asked for another assist than the game's.
    if (options.assist != resumed.assist)
        resumed.notices.push_back(std::string("This game keeps its assist, ") +
                                  assist_name(resumed.assist) + "; --assist is for new games");
    const int status = in_terminal(resumed, [&](App& app) { app.resume(std::move(chosen.game)); });
    tell_where_saved(path, std::nullopt, true);
    return status;
}

// A new game in the first save no other game holds; `notices` are shown in the game.
int new_game(GameOptions options, std::vector<std::string> notices) {
    // A slot is taken only when its save is missing, over, or not a game at all (moved aside
    // then): a game left unfinished stays for --resume.
    SaveContents read;
    std::string kept; // where a save that is not a game went
    bool skipped = false;
    const SaveLock lock = claim_free_slot([&](const std::string& slot) {
        read = read_save(slot);
        if (read.problem)
            kept = keep_bad_save(slot);
        const bool free = new_game_may_take(read);
        skipped |= !free;
        return free;
    });
    const std::string& path = lock.path();
    if (slot_of(path) > 1)
        // In the game's own panel, where the command would not fit: on the way out the game
        // says how to continue each save.
        notices.push_back(std::string(skipped ? "An unfinished game is kept for --resume"
                                              : "Another termpool game is running") +
                          ": this one is saved in " + display_path(path));
    if (read.problem) {
        std::fprintf(stderr, "%s:%d: %s\n", path.c_str(), read.problem->line,
                     read.problem->message.c_str());
        notices.push_back("The old save could not be read; " + kept);
    }
    options.save_path = path;
    options.notices = std::move(notices);
    const std::optional<std::string> before = read.problem ? std::nullopt : read.text;
    const int status = in_terminal(options, [](App&) {});
    tell_where_saved(path, before, false);
    return status;
}

} // namespace

const char* game_options_usage() {
    return options_usage;
}

int run_game(const std::vector<std::string>& args) {
    // The config file's defaults first; the command line overrides them.
    GameOptions defaults;
    std::vector<std::string> notices;
    std::string config_error;
    const auto config = read_whole_file(config_path(), config_error, max_config_bytes);
    if (!config_error.empty()) {
        std::fprintf(stderr, "termpool: %s\n", config_error.c_str());
        return 2;
    }
    if (config) {
        std::vector<std::string> warnings;
        if (const auto bad = apply_config(*config, defaults, warnings)) {
            std::fprintf(stderr, "%s:%s\n", config_path().c_str(), bad->c_str());
            return 2;
        }
        // On stderr for the record, and in the game, where the player is looking.
        for (const std::string& w : warnings) {
            std::fprintf(stderr, "termpool: warning: %s\n", w.c_str());
            notices.push_back("Warning: " + w);
        }
    }
    std::string error;
    const auto options = parse_game_options(args, error, defaults);
    if (!options) {
        std::fprintf(stderr, "termpool: %s\n", error.c_str());
        print_game_usage(stderr);
        return 2;
    }
    if (options->help) {
        print_game_usage(stdout);
        return 0;
    }
    return options->resume ? resume_game(*options, notices)
                           : new_game(*options, std::move(notices));
}

int run_practice(const std::vector<std::string>& args) {
    GameOptions defaults;
    std::string config_error;
    std::vector<std::string> warnings;
    const auto config = read_whole_file(config_path(), config_error, max_config_bytes);
    if (!config_error.empty()) {
        std::fprintf(stderr, "termpool: %s\n", config_error.c_str());
        return 2;
    }
    if (config) {
        if (const auto bad = apply_config(*config, defaults, warnings)) {
            std::fprintf(stderr, "%s:%s\n", config_path().c_str(), bad->c_str());
            return 2;
        }
    }
    std::string error;
    auto options = parse_game_options(args, error, defaults);
    if (options)
        for (const std::string& w : warnings)
            options->notices.push_back("Warning: " + w);
    const bool two_players = std::any_of(args.begin(), args.end(), [](const std::string& a) {
        return a == "--player2" || a == "--race" || a == "--breaks";
    });
    if (options && (options->resume || options->watch || options->computer || two_players))
        error = "practice is one player at the table: no --player2, --race, --breaks, --resume, "
                "--vs-computer or --watch";
    constexpr const char* usage =
        "usage: termpool practice [--game 8ball|8ball-bar|9ball|10ball]\n"
        "                         [--table 7ft|8ft|9ft|snooker]\n"
        "                         [--player1 NAME] [--seed S] [--assist A] [--friction MODEL]\n"
        "                         [--cue-ball-mass KG] [--cue SHAFT] [--ascii]\n"
        "One player at the table, no referee: m moves a ball, r takes the last shot again,\n"
        "t racks again.\n";
    if (options && options->help) {
        std::fputs(usage, stdout);
        return 0;
    }
    if (!options || !error.empty()) {
        std::fprintf(stderr, "termpool: %s\n%s", error.c_str(), usage);
        return 2;
    }
    options->practice = true;
    options->race_to = 1; // a config file's race is for games
    return in_terminal(*options, [](App&) {});
}

int run_replay(const std::vector<std::string>& args) {
    constexpr const char* usage = "usage: termpool replay [FILE]   (default: the game saved "
                                  "last)\n  space pauses, Left/Right step a shot, x skips the "
                                  "animation, q quits\n";
    if (args.size() == 1 && (args[0] == "-h" || args[0] == "--help")) {
        std::fputs(usage, stdout);
        return 0;
    }
    if (args.size() > 1) {
        std::fputs(usage, stderr);
        return 2;
    }
    std::string path = args.empty() ? "" : args[0];
    if (path.empty()) {
        // The save written last, whichever game holds it: a replay only reads.
        std::pair<std::time_t, long> newest{0, 0};
        for (const int slot : existing_slots()) {
            struct stat st {};
            if (::stat(slot_path(slot).c_str(), &st) != 0)
                continue;
            const std::pair<std::time_t, long> written{st.st_mtim.tv_sec, st.st_mtim.tv_nsec};
            if (path.empty() || written > newest) {
                newest = written;
                path = slot_path(slot);
            }
        }
        if (path.empty()) {
            std::fprintf(stderr, "termpool: no saved game to replay (%s)\n",
                         display_path(save_dir()).c_str());
            return 1;
        }
    }
    std::string error;
    const std::optional<std::string> text = read_whole_file(path, error, max_save_bytes);
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
    const GameRecord& record = std::get<Match>(result).record();
    return in_terminal(options_from(record, GameOptions{}),
                       [&](App& app) { app.start_replay(record); });
}

} // namespace termpool::tui
