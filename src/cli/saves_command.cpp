#include "cli/saves_command.hpp"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <optional>

#include "files/self_command.hpp"
#include "player/save_file.hpp"
#include "player/save_list.hpp"
#include "player/save_slots.hpp"
#include "player/save_summary.hpp"

namespace termpool::cli {
namespace {

constexpr const char* usage = "usage: termpool saves [--remove N] [--help]\n";

constexpr const char* help =
    "usage: termpool saves [--remove N] [--help]\n"
    "\n"
    "Lists the saved games that can be continued, newest first, each with its number\n"
    "(termpool --resume N continues save N), the players, the game, how far it went and\n"
    "when it was saved. Finished games are not listed: they stay for termpool replay.\n"
    "The saves are in $XDG_STATE_HOME/termpool/ (~/.local/state/termpool/).\n"
    "\n"
    "  --remove N   remove save N (not one being played in another terminal)\n"
    "  -h, --help   print this help and exit\n";

int remove(const std::string& which) {
    const int slot = parse_slot_number(which);
    std::string error;
    const Removal removal = slot > 0 ? remove_save(slot, error) : Removal::missing;
    switch (removal) {
    case Removal::removed:
        std::printf("Removed save %d.\n", slot);
        return 0;
    case Removal::missing:
    case Removal::finished:
    case Removal::not_a_game: {
        // Not one of the numbers `termpool saves` lists: nothing is removed.
        if (removal != Removal::missing)
            std::fprintf(stderr, "termpool saves: %s\n",
                         removal_words(removal, slot, error).c_str());
        else
            std::fprintf(stderr, "termpool saves: there is no save %s (%s saves lists them)\n",
                         which.c_str(), self_command().c_str());
        return 2;
    }
    case Removal::in_use:
    case Removal::changed:
    case Removal::failed:
        std::fprintf(stderr, "termpool saves: %s\n", removal_words(removal, slot, error).c_str());
        return 1;
    }
    return 1;
}

} // namespace

int saves_command(const std::vector<std::string>& args) {
    std::optional<std::string> to_remove;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--help" || args[i] == "-h") {
            std::fputs(help, stdout);
            return 0;
        }
        if (args[i] == "--remove" && i + 1 < args.size() && !to_remove) {
            to_remove = args[++i];
            continue;
        }
        std::fprintf(stderr, "termpool saves: %s '%s'\n%s",
                     args[i] == "--remove" ? "--remove needs one N, not" : "unknown argument",
                     args[i].c_str(), usage);
        return 2;
    }
    if (to_remove)
        return remove(*to_remove);

    const std::time_t now = std::time(nullptr);
    std::vector<SlotSave> saves = read_slot_saves();
    // What cannot be continued is said on stderr: the list is the saves to continue.
    for (const SlotSave& s : saves)
        if (s.contents.problem)
            std::fprintf(stderr, "termpool: %s:%d: %s (not a game; not listed)\n",
                         display_path(s.path()).c_str(), s.contents.problem->line,
                         s.contents.problem->message.c_str());
        else if (!s.contents.error.empty())
            std::fprintf(stderr, "termpool: %s\n", s.contents.error.c_str());
    saves = unfinished_saves(std::move(saves));
    if (saves.empty()) {
        std::printf("No saved game to continue (in %s).\n", display_path(save_dir()).c_str());
        return 0;
    }
    std::printf("Saved games you can continue, newest first (%s --resume N):\n",
                self_command().c_str());
    for (const SlotSave& s : saves)
        std::printf("%s\n", save_line(s, now).c_str());
    return 0;
}

} // namespace termpool::cli
