#pragma once
// Several games under one account: each running game holds a lock on its own save, so a
// second game started beside the first is saved in game-2.save instead of overwriting it.
// The saves are numbered slots in the save directory: 1 is game.save, N is game-N.save.

#include <functional>
#include <string>
#include <vector>

namespace termpool {

/// The save number `text` names: 1 to 3 digits, as the lists number saves; 0 for anything else.
int parse_slot_number(const std::string& text);

/// The path of slot `slot` (>= 1) in the save directory.
std::string slot_path(int slot);

/// The slot a path names (the save directory's game.save or game-N.save), or 0.
int slot_of(const std::string& path);

/// The slots that have a save file, in order.
std::vector<int> existing_slots();

/// `path` with $HOME shown as ~, for messages.
std::string display_path(const std::string& path);

/// An exclusive lock on one save, held for the life of the value. It is a flock on SAVE.lock
/// beside the save: the save itself is replaced by every atomic write, so it cannot carry one.
class SaveLock {
public:
    /// What trying the lock gave.
    enum class State {
        held,       ///< this value holds it
        busy,       ///< another game holds it
        unavailable ///< the lock file cannot be made (no directory, read-only): not locked
    };
    /// Tries to lock the save at `save_path` without waiting (its directory must exist).
    explicit SaveLock(std::string save_path);
    /// Releases the lock.
    ~SaveLock();
    SaveLock(SaveLock&& other) noexcept;
    SaveLock& operator=(SaveLock&& other) noexcept;
    SaveLock(const SaveLock&) = delete;
    SaveLock& operator=(const SaveLock&) = delete;

    /// What trying the lock gave.
    State state() const { return state_; }
    /// The save this lock is for.
    const std::string& path() const { return path_; }

private:
    std::string path_;
    int fd_ = -1;
    State state_ = State::unavailable;
};

/// The first slot no other game holds and `may_take` accepts (it is asked with the slot
/// locked), locked: game.save unless another game runs in it or it is kept. The save directory
/// is created. Where no lock can be made (a read-only directory) the slot comes back unlocked
/// (State::unavailable), and the game plays there as before locks.
SaveLock claim_free_slot(const std::function<bool(const std::string& path)>& may_take);

} // namespace termpool
