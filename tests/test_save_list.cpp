// The saves as a player sees them (src/player): newest first, finished games left out, one
// removed on request (only the slot's own file, never one in use or replaced meanwhile), the
// freed slot taken by the next new game, the --resume question, and a save in words.
#include <catch2/catch.hpp>
#include <cstdio>
#include <ctime>
#include <fcntl.h>
#include <string>
#include <sys/stat.h>
#include <termpool/match.hpp>
#include <termpool/record.hpp>
#include <unistd.h>

#include "files/atomic_file.hpp"
#include "player/save_file.hpp"
#include "player/save_list.hpp"
#include "player/save_summary.hpp"
#include "scoped_env.hpp"
#include "temp_dir.hpp"
#include "tui/save_prompt.hpp"

using namespace termpool;
using namespace termpool::tui;

namespace {

// A save of `first` v `second` before the break: a game to continue.
std::string unfinished_save(const std::string& first = "Ann", const std::string& second = "Bob") {
    GameRecord record;
    record.seed = 3;
    record.names[0] = first;
    record.names[1] = second;
    return format_record(record);
}

// A snooker frame Ann conceded at once: a game that is over, Bob the winner.
std::string finished_save() {
    GameRecord header;
    header.setup.game = GameType::snooker;
    header.setup.table = TableSize::snooker;
    header.seed = 11;
    header.names[0] = "Ann";
    header.names[1] = "Bob";
    auto started = Match::start(header);
    REQUIRE(std::holds_alternative<Match>(started));
    Match match = std::move(std::get<Match>(started));
    REQUIRE(match.concede(1) == MatchError::none);
    REQUIRE(match.pending().kind == Pending::over);
    return format_record(match.record());
}

// Writes `text` as save `slot`, last written at `when`.
void write_slot(int slot, const std::string& text, std::time_t when) {
    std::string error;
    REQUIRE(write_atomically(slot_path(slot), text, error));
    const timespec times[2] = {{when, 0}, {when, 0}};
    REQUIRE(::utimensat(AT_FDCWD, slot_path(slot).c_str(), times, 0) == 0);
}

bool exists(const std::string& path) {
    struct stat st {};
    return ::lstat(path.c_str(), &st) == 0;
}

std::vector<int> slots_of(const std::vector<SlotSave>& saves) {
    std::vector<int> slots;
    for (const SlotSave& s : saves)
        slots.push_back(s.slot);
    return slots;
}

// The saves in a scratch state folder, for one test.
struct SaveFolder {
    test::TempDir dir{"termpool-save-list"};
    test::ScopedEnv state{"XDG_STATE_HOME", dir.path()};
    SaveFolder() { REQUIRE(make_directories(save_dir()).empty()); }
};

} // namespace

TEST_CASE("how long ago a save was written, in words", "[save]") {
    const std::time_t t = 1'700'000'000;
    CHECK(age_words(t, t) == "just now");
    CHECK(age_words(t, t + 59) == "just now");
    CHECK(age_words(t + 100, t) == "just now"); // a clock set back
    CHECK(age_words(t, t + 60) == "1 minute ago");
    CHECK(age_words(t, t + 119) == "1 minute ago");
    CHECK(age_words(t, t + 120) == "2 minutes ago");
    CHECK(age_words(t, t + 3600) == "1 hour ago");
    CHECK(age_words(t, t + 5 * 3600 + 59) == "5 hours ago");
    CHECK(age_words(t, t + 86400) == "1 day ago");
    CHECK(age_words(t, t + 29 * 86400) == "29 days ago");
    const std::string old = age_words(t, t + 30 * 86400);
    CHECK(old.starts_with("on 2023-11-1")); // the local date, 14 or 15 November
    CHECK(old.size() == std::string("on 2023-11-14").size());
}

TEST_CASE("a save in a list: its number, the players, the game, how far, how long ago", "[save]") {
    const SaveFolder folder;
    const std::time_t now = std::time(nullptr);
    write_slot(2, unfinished_save(), now - 300);
    CHECK(save_line(read_slot_save(2), now) ==
          "  2  Ann v Bob, 8ball, 9ft, 0 shots, saved 5 minutes ago");
    write_slot(1, finished_save(), now - 7200);
    const SlotSave over = read_slot_save(1);
    REQUIRE(over.contents.game);
    CHECK(game_summary(*over.contents.game) == "Ann v Bob, snooker, won by Bob");
    CHECK(save_words(over, now) == "Ann v Bob, snooker, won by Bob, saved 2 hours ago");
    // Another game playing it says so.
    const SaveLock other(slot_path(2));
    REQUIRE(other.state() == SaveLock::State::held);
    CHECK(save_line(read_slot_save(2), now).ends_with(", being played in another terminal"));
}

TEST_CASE("the saves are listed newest first; the finished ones are not offered", "[save]") {
    const SaveFolder folder;
    write_slot(1, unfinished_save(), 1000);
    write_slot(2, finished_save(), 4000);
    write_slot(3, unfinished_save(), 3000);
    write_slot(4, "termpool-record 1\ngame pool\nend\n", 5000);
    write_slot(5, unfinished_save(), 2000);
    std::vector<SlotSave> all = read_slot_saves();
    CHECK(slots_of(all) == std::vector<int>{4, 2, 3, 5, 1});
    CHECK(all[0].contents.problem);
    CHECK(all[1].contents.game);
    CHECK_FALSE(all[1].contents.unfinished());
    CHECK(slots_of(unfinished_saves(std::move(all))) == std::vector<int>{3, 5, 1});
    // Saved at the same moment: the lower number first.
    write_slot(5, unfinished_save(), 3000);
    CHECK(slots_of(unfinished_saves(read_slot_saves())) == std::vector<int>{3, 5, 1});
    // Every file is left as it was.
    CHECK(exists(slot_path(2)));
    CHECK(exists(slot_path(4)));
}

TEST_CASE("a save is removed only when it is an unfinished game no one plays", "[save]") {
    const SaveFolder folder;
    std::string error;
    write_slot(1, finished_save(), 1000);
    write_slot(2, unfinished_save(), 1000);
    write_slot(3, unfinished_save(), 1000);
    write_slot(4, "not a save\n", 1000);

    CHECK(remove_save(2, error) == Removal::removed);
    CHECK(error.empty());
    CHECK_FALSE(exists(slot_path(2)));
    CHECK(exists(slot_path(3)));
    CHECK(remove_save(2, error) == Removal::missing); // once only

    // Kept: a finished game (for termpool replay), a file that is not a game.
    CHECK(remove_save(1, error) == Removal::finished);
    CHECK(exists(slot_path(1)));
    CHECK(remove_save(4, error) == Removal::not_a_game);
    CHECK(exists(slot_path(4)));

    // No such save: nothing made for it either.
    for (const int slot : {0, -1, 7, 1000})
        CHECK(remove_save(slot, error) == Removal::missing);
    CHECK_FALSE(exists(slot_path(7) + ".lock"));

    // Another game playing it holds its lock.
    {
        const SaveLock playing(slot_path(3));
        REQUIRE(playing.state() == SaveLock::State::held);
        CHECK(remove_save(3, error) == Removal::in_use);
        CHECK(exists(slot_path(3)));
    }
    CHECK(remove_save(3, error) == Removal::removed);

    // A slot that is a link: the link goes, never the file it points to.
    const std::string elsewhere = folder.dir.write("kept.save", unfinished_save());
    REQUIRE(::symlink(elsewhere.c_str(), slot_path(5).c_str()) == 0);
    CHECK(remove_save(5, error) == Removal::removed);
    CHECK_FALSE(exists(slot_path(5)));
    CHECK(exists(elsewhere));

    // A file replaced after it was read is not the one the player chose.
    write_slot(6, unfinished_save(), 1000);
    {
        const SlotSave chosen = read_slot_save(6);
        REQUIRE(write_atomically(slot_path(6), unfinished_save("Cy", "Dee"), error));
        CHECK(remove_slot_save(chosen, error) == Removal::changed);
        CHECK(exists(slot_path(6)));
    }

    // A save read (and so locked) by this very list is removed under its own lock.
    const SlotSave listed = read_slot_save(6);
    CHECK(listed.lock.state() == SaveLock::State::held);
    CHECK(remove_slot_save(listed, error) == Removal::removed);
    CHECK_FALSE(exists(slot_path(6)));
}

TEST_CASE("a new game takes the slot of a removed save", "[save]") {
    const SaveFolder folder;
    for (const int slot : {1, 2, 3})
        write_slot(slot, unfinished_save(), 1000);
    const auto new_game_slot = [] {
        const SaveLock lock = claim_free_slot(
            [](const std::string& path) { return new_game_may_take(read_save(path)); });
        return slot_of(lock.path());
    };
    CHECK(new_game_slot() == 4); // every unfinished game is kept
    std::string error;
    REQUIRE(remove_save(2, error) == Removal::removed);
    CHECK(new_game_slot() == 2);
    // A finished game's slot is taken too; one that is not a game is (moved aside first).
    write_slot(2, unfinished_save(), 1000);
    write_slot(1, finished_save(), 1000);
    CHECK(new_game_slot() == 1);
    CHECK(new_game_may_take(read_save(folder.dir.write("bad.save", "junk\n"))));
    CHECK(new_game_may_take(read_save(folder.dir.path() + "/none.save")));
    CHECK_FALSE(new_game_may_take(read_save(folder.dir.write("on.save", unfinished_save()))));
}

namespace {

// pick_save with `typed` as the player's answers: what it chose (a slot, 0 for none) and
// what it printed.
std::pair<int, std::string> pick(std::vector<SlotSave>& saves, const std::string& typed) {
    std::FILE* in = std::tmpfile();
    REQUIRE(in);
    std::fputs(typed.c_str(), in);
    std::rewind(in);
    char* printed = nullptr;
    std::size_t size = 0;
    std::FILE* out = open_memstream(&printed, &size);
    REQUIRE(out);
    const auto chosen = pick_save(saves, in, out, std::time(nullptr));
    std::fclose(out);
    std::fclose(in);
    std::string text(printed, size);
    std::free(printed);
    return {chosen ? saves.at(*chosen).slot : 0, text};
}

} // namespace

TEST_CASE("the --resume question: a number, Enter, d N with a yes or a no, q", "[save]") {
    const SaveFolder folder;
    write_slot(1, unfinished_save("Ann", "Bob"), 1000);
    write_slot(2, unfinished_save("Cy", "Dee"), 3000);
    write_slot(3, unfinished_save("Eve", "Fay"), 2000);
    const auto listed = [] { return unfinished_saves(read_slot_saves()); };

    {
        auto saves = listed();
        const auto [slot, out] = pick(saves, "3\n");
        CHECK(slot == 3);
        CHECK(out.starts_with("Saved games you can continue, newest first:\n"
                              "  2  Cy v Dee, 8ball, 9ft, 0 shots, saved on "));
        CHECK(out.find("\n  3  Eve v Fay") < out.find("\n  1  Ann v Bob"));
        CHECK(
            out.ends_with("Continue which? Its number (Enter: 2), d N removes save N, q quits: "));
    }
    {
        auto saves = listed();
        CHECK(pick(saves, "\n").first == 2); // Enter: the newest
        CHECK(pick(saves, "q\n").first == 0);
        CHECK(pick(saves, "").first == 0); // the end of the input
        const auto [slot, out] = pick(saves, "7\nx\n1\n");
        CHECK(slot == 1);
        CHECK(out.find("There is no save 7 in the list.\n") != std::string::npos);
        CHECK(out.find("Type a save's number, d N to remove save N, or q.\n") != std::string::npos);
    }
    {
        // A no keeps it.
        auto saves = listed();
        const auto [slot, out] = pick(saves, "d\n3\nn\nq\n");
        CHECK(slot == 0);
        CHECK(out.find("Remove which save? Remove save 3 (Eve v Fay, 8ball, 9ft, 0 shots, "
                       "saved on ") != std::string::npos);
        CHECK(out.find(")? y/n Save 3 is kept.\n") != std::string::npos);
        CHECK(exists(slot_path(3)));
        CHECK(saves.size() == 3);
    }
    {
        // A yes removes it, from the folder and from the list, and the list is shown again.
        auto saves = listed();
        const auto [slot, out] = pick(saves, "d 3\ny\n1\n");
        CHECK(slot == 1);
        CHECK(out.find("Removed save 3.\nSaved games you can continue") != std::string::npos);
        CHECK_FALSE(exists(slot_path(3)));
        CHECK(slots_of(saves) == std::vector<int>{2, 1});
    }
    {
        // Not a number in the list: nothing removed.
        auto saves = listed();
        const auto [slot, out] = pick(saves, "d 9\nd9\nq\n");
        CHECK(out.find("There is no save 9 in the list.") != std::string::npos);
        CHECK(saves.size() == 2);
        // Removing them all leaves nothing to pick.
        const auto [none, all_gone] = pick(saves, "d2\nyes\nd 1\ny\n");
        CHECK(none == 0);
        CHECK(all_gone.ends_with("Removed save 1.\nNo saved game left to continue.\n"));
        CHECK(existing_slots().empty());
    }
}
