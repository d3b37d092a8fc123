#include "tui/save_prompt.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include "player/save_slots.hpp"
#include "player/save_summary.hpp"

namespace termpool::tui {
namespace {

// One answer: a line of `in` without its spaces at either end, at most 255 bytes of it (the
// rest of a longer line is skipped); nothing at the end of the input.
std::optional<std::string> read_answer(std::FILE* in, std::FILE* out) {
    std::fflush(out);
    char line[256];
    if (!std::fgets(line, sizeof line, in)) {
        std::fputc('\n', out); // the prompt's line ends where the input did
        return std::nullopt;
    }
    if (!std::strchr(line, '\n'))
        for (int c = std::fgetc(in); c != EOF && c != '\n'; c = std::fgetc(in)) {
        }
    std::string answer(line);
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    while (!answer.empty() && blank(answer.back()))
        answer.pop_back();
    answer.erase(0, std::min(answer.size(), answer.find_first_not_of(" \t")));
    return answer;
}

// True when `text` is a number a save may have (parse_slot_number).
bool number(const std::string& text) {
    return parse_slot_number(text) > 0;
}

// The number after d in "d 2", "d2" or "d" (empty: to be asked), when `answer` asks for a
// removal.
std::optional<std::string> removal_asked(const std::string& answer) {
    if (answer.empty() || (answer[0] != 'd' && answer[0] != 'D'))
        return std::nullopt;
    std::string which = answer.substr(1);
    which.erase(0, std::min(which.size(), which.find_first_not_of(" \t")));
    if (!which.empty() && !number(which))
        return std::nullopt;
    return which;
}

// The save numbered `text` in `saves`, or saves.size() when there is none.
std::size_t find_save(const std::vector<SlotSave>& saves, const std::string& text) {
    const int slot = parse_slot_number(text);
    if (slot == 0)
        return saves.size();
    return static_cast<std::size_t>(
        std::find_if(saves.begin(), saves.end(),
                     [&](const SlotSave& s) { return s.slot == slot; }) -
        saves.begin());
}

void print_list(const std::vector<SlotSave>& saves, std::FILE* out, std::time_t now) {
    std::fputs("Saved games you can continue, newest first:\n", out);
    for (const SlotSave& s : saves)
        std::fprintf(out, "%s\n", save_line(s, now).c_str());
}

// Asks whether to remove save `which` (given as typed, or asked for), and removes it on a yes.
// False at the end of the input.
bool offer_removal(std::vector<SlotSave>& saves, std::string which, std::FILE* in, std::FILE* out,
                   std::time_t now) {
    if (which.empty()) {
        std::fputs("Remove which save? ", out);
        const auto answer = read_answer(in, out);
        if (!answer)
            return false;
        which = *answer;
    }
    const std::size_t i = find_save(saves, which);
    if (i == saves.size()) {
        std::fprintf(out, "There is no save %s in the list.\n", which.c_str());
        return true;
    }
    const SlotSave& save = saves[i];
    std::fprintf(out, "Remove save %d (%s)? y/n ", save.slot, save_words(save, now).c_str());
    const auto answer = read_answer(in, out);
    if (!answer)
        return false;
    if (*answer != "y" && *answer != "Y" && *answer != "yes") {
        std::fprintf(out, "Save %d is kept.\n", save.slot);
        return true;
    }
    std::string error;
    const Removal removal = remove_slot_save(save, error);
    if (removal == Removal::removed) {
        std::fprintf(out, "Removed save %d.\n", save.slot);
        saves.erase(saves.begin() + static_cast<std::ptrdiff_t>(i));
        if (!saves.empty())
            print_list(saves, out, now);
    } else {
        std::fprintf(out, "Not removed: %s\n", removal_words(removal, save.slot, error).c_str());
    }
    return true;
}

} // namespace

std::optional<std::size_t> pick_save(std::vector<SlotSave>& saves, std::FILE* in, std::FILE* out,
                                     std::time_t now) {
    print_list(saves, out, now);
    while (!saves.empty()) {
        std::fprintf(out, "Continue which? Its number (Enter: %d), d N removes save N, q quits: ",
                     saves.front().slot);
        const auto answer = read_answer(in, out);
        if (!answer || *answer == "q" || *answer == "Q")
            return std::nullopt;
        if (answer->empty())
            return 0;
        if (const auto which = removal_asked(*answer)) {
            if (!offer_removal(saves, *which, in, out, now))
                return std::nullopt;
            continue;
        }
        if (!number(*answer))
            std::fputs("Type a save's number, d N to remove save N, or q.\n", out);
        else if (const std::size_t i = find_save(saves, *answer); i < saves.size())
            return i;
        else
            std::fprintf(out, "There is no save %s in the list.\n", answer->c_str());
    }
    std::fputs("No saved game left to continue.\n", out);
    return std::nullopt;
}

} // namespace termpool::tui
