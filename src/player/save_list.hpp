#pragma once
// The saves of the save directory's slots as a player sees them: read, newest first, those to
// continue told from those that are over, and one removed on request. Any front end lists and
// removes saves through this (the terminal game's --resume, `termpool saves`); the numbers are
// the slots' (save N is game-N.save, 1 is game.save), so they stay the same between listings.

#include <ctime>
#include <string>
#include <sys/types.h>
#include <vector>

#include "player/save_read.hpp"
#include "player/save_slots.hpp"

namespace termpool {

/// One slot's save, read, with its lock tried (and held, when it could be, for as long as the
/// value lives: a game continued from it keeps it).
struct SlotSave {
    int slot = 0;            ///< 1 is game.save, N is game-N.save
    SaveLock lock;           ///< busy when another game is playing this save
    std::timespec written{}; ///< when the file was last written (its modification time)
    SaveContents contents;   ///< the file and the game in it
    dev_t entry_device = 0;  ///< the slot's directory entry as it was read (a link's own),
    ino_t entry_inode = 0;   ///< so that a removal knows it is still the same file

    /// The save's file.
    const std::string& path() const { return lock.path(); }
    /// True when another game is playing it.
    bool in_use() const { return lock.state() == SaveLock::State::busy; }
};

/// The save of slot `slot`, read (missing when there is no file), its lock tried.
SlotSave read_slot_save(int slot);

/// Every slot's save, newest first (by the time it was last written; at the same time, the
/// lower slot first).
std::vector<SlotSave> read_slot_saves();

/// The saves of `saves` that hold an unfinished game, in the same order: those a player may
/// be offered to continue (or to remove). Finished games, files that are not a game and
/// those that cannot be read are left out.
std::vector<SlotSave> unfinished_saves(std::vector<SlotSave> saves);

/// True when a new game may take the place of `save`: there is none (never was, or removed),
/// its game is over, or it is not a game (the caller moves it aside first). An unfinished game
/// stays for --resume, and so does a file that cannot be read.
bool new_game_may_take(const SaveContents& save);

/// How a removal ended.
enum class Removal {
    removed,    ///< the file is gone
    missing,    ///< there is no such save
    finished,   ///< the save holds a game that is over: kept for `termpool replay`
    not_a_game, ///< the file is not a game, or cannot be read: left alone
    in_use,     ///< another game is playing it: left alone
    changed,    ///< the file was replaced while it was being checked: left alone
    failed,     ///< it could not be removed (the error says why)
};

/// Removes the unfinished save `save`, whose lock the value holds (or which cannot be locked
/// at all: a read-only folder, where the removal fails in its turn). Only the slot's own
/// directory entry goes (a link is removed, never what it points to), in one unlink, and only
/// when it is still the file that was read and an unfinished game. `error` says why it failed.
Removal remove_slot_save(const SlotSave& save, std::string& error);

/// Removes save `slot` as `remove_slot_save` does, after reading it and locking it.
Removal remove_save(int slot, std::string& error);

} // namespace termpool
