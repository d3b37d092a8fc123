#include "player/save_list.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

#include "player/save_file.hpp"

namespace termpool {

SlotSave read_slot_save(int slot) {
    SlotSave save{slot, SaveLock(slot_path(slot)), {}, {}, 0, 0};
    struct stat entry {};
    if (::lstat(save.path().c_str(), &entry) != 0)
        return save; // missing: nothing to read
    save.entry_device = entry.st_dev;
    save.entry_inode = entry.st_ino;
    struct stat file {};
    save.written = ::stat(save.path().c_str(), &file) == 0 ? file.st_mtim : entry.st_mtim;
    save.contents = read_save(save.path());
    return save;
}

std::vector<SlotSave> read_slot_saves() {
    std::vector<SlotSave> saves;
    for (const int slot : existing_slots())
        saves.push_back(read_slot_save(slot));
    std::stable_sort(saves.begin(), saves.end(), [](const SlotSave& a, const SlotSave& b) {
        return std::pair(a.written.tv_sec, a.written.tv_nsec) >
               std::pair(b.written.tv_sec, b.written.tv_nsec);
    });
    return saves;
}

std::vector<SlotSave> unfinished_saves(std::vector<SlotSave> saves) {
    std::erase_if(saves, [](const SlotSave& s) { return !s.contents.unfinished(); });
    return saves;
}

bool new_game_may_take(const SaveContents& save) {
    return save.missing() || save.problem || (save.game && finished(*save.game));
}

Removal remove_slot_save(const SlotSave& save, std::string& error) {
    error.clear();
    if (save.in_use())
        return Removal::in_use;
    if (save.contents.missing())
        return Removal::missing;
    if (save.contents.game && finished(*save.contents.game))
        return Removal::finished;
    if (!save.contents.unfinished())
        return Removal::not_a_game;
    // The lock keeps every termpool game out of the slot; anything else that replaced the
    // file since it was read is left alone.
    struct stat entry {};
    if (::lstat(save.path().c_str(), &entry) != 0)
        return errno == ENOENT ? Removal::missing : Removal::changed;
    if (entry.st_dev != save.entry_device || entry.st_ino != save.entry_inode)
        return Removal::changed;
    // unlink removes the directory entry itself, never what a link points to.
    if (::unlink(save.path().c_str()) != 0) {
        error = save.path() + ": cannot remove: " + std::strerror(errno);
        return Removal::failed;
    }
    // The removal is durable once the folder is synced.
    if (const int dir = ::open(save_dir().c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
    return Removal::removed;
}

Removal remove_save(int slot, std::string& error) {
    error.clear();
    struct stat entry {};
    if (slot < 1 || slot_of(slot_path(slot)) != slot ||
        ::lstat(slot_path(slot).c_str(), &entry) != 0)
        return Removal::missing; // checked first: no lock file is made for a slot never used
    return remove_slot_save(read_slot_save(slot), error);
}

} // namespace termpool
