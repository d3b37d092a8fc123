#include "tui/game_main.hpp"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <functional>
#include <stdexcept>
#include <sys/stat.h>
#include <utility>
#include <variant>

#include "files/keep_aside.hpp"
#include "files/self_command.hpp"
#include "player/config.hpp"
#include "player/options.hpp"
#include "player/save_file.hpp"
#include "player/save_slots.hpp"
#include "tui/app.hpp"

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
    "  --resume [N | FILE]   continue a saved game: the only one, save N (1 is game.save,\n"
    "                        N is game-N.save) or FILE; with several, list them\n"
    "  -h, --help            print this help and exit\n"
    "Defaults come from $XDG_CONFIG_HOME/termpool/config (~/.config/termpool/config);\n"
    "games are saved in $XDG_STATE_HOME/termpool/ (~/.local/state/termpool/).\n";

void print_game_usage(std::FILE* out) {
    std::fprintf(out, "usage: termpool [OPTIONS]   (commands: termpool --help)\n%s", options_usage);
}

// A saved game or match, read and replayed (once) to where it stands.
// A save read back: the match replayed to where its record stands.
std::variant<Match, RecordError> load_game(const std::string& text) {
    auto parsed = parse_record(text);
    if (auto* problem = std::get_if<RecordError>(&parsed))
        return *problem;
    return Match::replay(std::get<GameRecord>(parsed));
}

// True when the save holds a game or match that is over: a new game may take its place.
bool finished(const Match& saved) {
    return saved.pending().kind == Pending::over;
}

// A save read from disk, or why not: missing (nothing), unreadable (error), or not a game
// (problem; a slot's save is then moved aside as .bad, never overwritten).
struct SaveRead {
    std::optional<std::string> text;
    std::string error;
    std::optional<RecordError> problem;
    std::string kept_as;       // where a save that is not a game went
    std::string kept_as_error; // why it could not be moved there
    std::optional<Match> loaded;
};

// Where a save that is not a game was kept, in words.
std::string kept_words(const SaveRead& r) {
    return r.kept_as.empty() ? "it could not be moved aside (" + r.kept_as_error + ")"
                             : "it is kept as " + r.kept_as;
}

SaveRead read_save(const std::string& path) {
    SaveRead r;
    r.text = read_whole_file(path, r.error);
    if (!r.text)
        return r;
    auto result = load_game(*r.text);
    if (auto* problem = std::get_if<RecordError>(&result)) {
        r.problem = *problem;
        // A slot's save that cannot be read is moved aside, never over an older one.
        if (slot_of(path) != 0) {
            std::string why;
            if (const auto kept = keep_aside(path, why))
                r.kept_as = *kept;
            else
                r.kept_as_error = why;
        }
    } else {
        r.loaded.emplace(std::move(std::get<Match>(result)));
    }
    return r;
}

void report_bad_save(const std::string& path, const SaveRead& read) {
    std::fprintf(stderr, "%s:%d: %s\n", path.c_str(), read.problem->line,
                 read.problem->message.c_str());
    if (slot_of(path) != 0)
        std::fprintf(stderr, "termpool: %s\n", kept_words(read).c_str());
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
    std::string ignored;
    const std::optional<std::string> after = read_whole_file(path, ignored);
    if (!after || (!resumed && after == before))
        return; // nothing was played (the names were never entered)
    // A game that is over has nothing to continue: it can be watched again.
    const auto loaded = load_game(*after);
    if (const auto* game = std::get_if<Match>(&loaded); game && finished(*game)) {
        std::printf("Game over, saved in %s; watch it again with: %s replay %s\n",
                    display_path(path).c_str(), self_command().c_str(), display_path(path).c_str());
        return;
    }
    std::printf("Game saved in %s; continue it with: %s\n", display_path(path).c_str(),
                resume_command(path).c_str());
}

// One line of the --resume list: the slot, the players, the game, how far, when.
std::string describe(int slot, const std::string& path, const Match& saved) {
    const GameRecord& r = saved.record();
    const auto shots = std::count_if(r.actions.begin(), r.actions.end(), [](const auto& a) {
        return a.kind == RecordedAction::Kind::shot;
    });
    const MatchState& score = saved.score();
    const int winner = score.is_race() ? score.match_winner() : saved.game().winner();
    std::string progress = winner != 0 ? "won by " + r.names[winner - 1]
                                       : std::to_string(shots) + (shots == 1 ? " shot" : " shots");
    if (score.is_race() && winner == 0)
        progress += ", race to " + std::to_string(score.race_to) + " at " +
                    std::to_string(score.racks_won[0]) + "-" + std::to_string(score.racks_won[1]);
    char when[32] = "";
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) {
        std::tm local{};
        if (localtime_r(&st.st_mtime, &local))
            std::strftime(when, sizeof when, "%Y-%m-%d %H:%M", &local);
    }
    char line[512];
    std::snprintf(line, sizeof line, "  %d  %s v %s, %s, %s, %s, saved %s  (%s)", slot,
                  r.names[0].c_str(), r.names[1].c_str(), game_type_name(r.setup.game),
                  table_size_name(r.setup.table), progress.c_str(), when,
                  display_path(path).c_str());
    return line;
}

// A save chosen to go on with, locked for as long as the game runs.
struct Chosen {
    SaveLock lock;
    Match game;
};

// `--resume N` or `--resume FILE`: that save, or the exit status after saying why not.
std::variant<Chosen, int> resume_named(const std::string& which) {
    const bool number =
        std::all_of(which.begin(), which.end(), [](char c) { return c >= '0' && c <= '9'; });
    const int slot = number && which.size() <= 3 ? std::stoi(which) : 0;
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
    SaveRead read = read_save(path);
    if (read.problem) {
        report_bad_save(path, read);
        return 2;
    }
    if (!read.loaded) {
        std::fprintf(stderr, "termpool: no saved game to resume (%s)\n",
                     read.error.empty() ? path.c_str() : read.error.c_str());
        return 1;
    }
    return Chosen{std::move(lock), std::move(*read.loaded)};
}

// Plain `--resume`: the one save no other game holds, or a list of them to pick from.
std::variant<Chosen, int> resume_only() {
    std::vector<Chosen> free;
    std::vector<std::string> busy;
    bool bad = false;
    for (const int slot : existing_slots()) {
        const std::string path = slot_path(slot);
        SaveLock lock(path);
        if (lock.state() == SaveLock::State::busy) {
            busy.push_back(display_path(path));
            continue;
        }
        SaveRead read = read_save(path);
        if (read.problem) {
            report_bad_save(path, read);
            bad = true;
        } else if (read.loaded) {
            free.push_back(Chosen{std::move(lock), std::move(*read.loaded)});
        } else if (!read.error.empty()) {
            std::fprintf(stderr, "termpool: cannot read %s\n", read.error.c_str());
        }
    }
    if (free.size() == 1)
        return std::move(free.front());
    if (free.empty()) {
        if (bad)
            return 2;
        std::string why = display_path(save_dir());
        for (const std::string& b : busy)
            why += "; " + b + " is in use by another termpool game";
        std::fprintf(stderr, "termpool: no saved game to resume (%s)\n", why.c_str());
        return 1;
    }
    std::printf("Saved games you can continue (%s --resume N, or --resume FILE):\n",
                self_command().c_str());
    for (const Chosen& c : free)
        std::printf("%s\n", describe(slot_of(c.lock.path()), c.lock.path(), c.game).c_str());
    return 0;
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
    const int status = in_terminal(resumed, [&](App& app) { app.resume(std::move(chosen.game)); });
    tell_where_saved(path, std::nullopt, true);
    return status;
}

// A new game in the first save no other game holds; `notices` are shown in the game.
int new_game(GameOptions options, std::vector<std::string> notices) {
    // A slot is taken only when its save is missing, over, or not a game at all (moved aside
    // then): a game left unfinished stays for --resume.
    SaveRead read;
    bool skipped = false;
    const SaveLock lock = claim_free_slot([&](const std::string& slot) {
        read = read_save(slot);
        const bool free = read.problem || (!read.text && read.error.empty()) ||
                          (read.loaded && finished(*read.loaded));
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
        notices.push_back("The old save could not be read; " + kept_words(read));
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
    if (const auto config = read_whole_file(config_path(), config_error)) {
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
    if (const auto config = read_whole_file(config_path(), config_error)) {
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
    const GameRecord& record = std::get<Match>(result).record();
    return in_terminal(options_from(record, GameOptions{}),
                       [&](App& app) { app.start_replay(record); });
}

} // namespace termpool::tui
