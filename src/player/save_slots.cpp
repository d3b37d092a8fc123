#include "player/save_slots.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <dirent.h>
#include <fcntl.h>
#include <string_view>
#include <sys/file.h>
#include <unistd.h>
#include <utility>

#include "player/save_file.hpp"

namespace termpool {
namespace {

// More slots than anyone runs games at once; past it the last one is shared, unlocked.
constexpr int max_slots = 999;

// The slot of a save's file name: game.save is 1, game-N.save is N (2..max_slots), else 0.
int slot_of_name(const std::string& name) {
    if (name == "game.save")
        return 1;
    constexpr std::string_view prefix = "game-", suffix = ".save";
    if (!name.starts_with(prefix) || !name.ends_with(suffix))
        return 0;
    const std::string digits =
        name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    if (digits.empty() || digits.size() > 3 || digits.front() == '0' ||
        !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return 0;
    const int slot = std::atoi(digits.c_str());
    return slot >= 2 && slot <= max_slots ? slot : 0;
}

} // namespace

int parse_slot_number(const std::string& text) {
    const bool digits =
        !text.empty() && text.size() <= 3 &&
        std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
    return digits ? std::stoi(text) : 0;
}

std::string slot_path(int slot) {
    return save_dir() + (slot <= 1 ? "/game.save" : "/game-" + std::to_string(slot) + ".save");
}

int slot_of(const std::string& path) {
    const std::string dir = save_dir() + "/";
    return path.starts_with(dir) ? slot_of_name(path.substr(dir.size())) : 0;
}

std::vector<int> existing_slots() {
    std::vector<int> slots;
    DIR* dir = ::opendir(save_dir().c_str());
    if (!dir)
        return slots;
    while (const dirent* entry = ::readdir(dir))
        if (const int slot = slot_of_name(entry->d_name); slot != 0)
            slots.push_back(slot);
    ::closedir(dir);
    std::sort(slots.begin(), slots.end());
    return slots;
}

std::string display_path(const std::string& path) {
    const char* home = std::getenv("HOME");
    if (!home || !*home)
        return path;
    const std::string prefix = std::string(home) + "/";
    return path.starts_with(prefix) ? "~/" + path.substr(prefix.size()) : path;
}

SaveLock::SaveLock(std::string save_path) : path_(std::move(save_path)) {
    // Never through a link: O_CREAT would make its target.
    fd_ = ::open((path_ + ".lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0600);
    if (fd_ < 0)
        return;
    int locked;
    do
        locked = ::flock(fd_, LOCK_EX | LOCK_NB);
    while (locked != 0 && errno == EINTR);
    if (locked == 0) {
        state_ = State::held;
        remove_temporaries_of(path_); // what a game killed while saving left; none saves now
        return;
    }
    state_ = errno == EWOULDBLOCK ? State::busy : State::unavailable;
    ::close(fd_);
    fd_ = -1;
}

SaveLock::~SaveLock() {
    if (fd_ >= 0)
        ::close(fd_);
}

SaveLock::SaveLock(SaveLock&& other) noexcept
    : path_(std::move(other.path_)), fd_(std::exchange(other.fd_, -1)), state_(other.state_) {}

SaveLock& SaveLock::operator=(SaveLock&& other) noexcept {
    if (this != &other) {
        if (fd_ >= 0)
            ::close(fd_);
        path_ = std::move(other.path_);
        fd_ = std::exchange(other.fd_, -1);
        state_ = other.state_;
    }
    return *this;
}

SaveLock claim_free_slot(const std::function<bool(const std::string& path)>& may_take) {
    make_directories(save_dir());
    for (int slot = 1; slot < max_slots; ++slot) {
        SaveLock lock(slot_path(slot));
        if (lock.state() == SaveLock::State::held && may_take(lock.path()))
            return lock;
        if (lock.state() == SaveLock::State::unavailable)
            return lock; // no locks here at all: play unlocked, as before locks
    }
    return SaveLock(slot_path(max_slots));
}

} // namespace termpool
