#pragma once
// Files that are never left half written: a new temporary file of a name of its own in the same
// folder, fsync, rename over the old one, fsync of the folder. The game's saves, the
// statistics, the hall's tables and seat tokens are all written this way, and nothing else
// writes them.
//
// A temporary file is PATH.tmp.XXXXXX (six letters or digits from the kernel's random source),
// created with O_EXCL|O_NOFOLLOW, mode 0600: a file or a link someone put at that name, or at
// the PATH.tmp older builds used, is never opened, so writing through a planted link to
// another file cannot happen. The rename replaces PATH itself, even when PATH is a link.

#include <functional>
#include <string>

namespace termpool {

/// Creates `dir` and its parents (mode 0700) where they are missing. "" when all is well, else
/// why not ("DIR: strerror").
std::string make_directories(const std::string& dir);

/// Tries this many names for a temporary file before giving up: another file at each of them
/// is more than chance (62^6 names).
inline constexpr int temporary_name_attempts = 100;

/// A new, empty file `path`.tmp.XXXXXX, open for writing (O_EXCL, O_NOFOLLOW, O_CLOEXEC, mode
/// 0600); its name goes to `temporary`. `next_suffix` gives each name's last part to try
/// (random by default; a test gives its own). -1 (with `error` naming the file and the
/// problem) when it cannot be made, or when temporary_name_attempts names were all taken.
int create_temporary(const std::string& path, std::string& temporary, std::string& error,
                     const std::function<std::string()>& next_suffix = {});

/// Writes `text` to `path` atomically, creating its folder: a temporary file
/// (create_temporary) is written, synced and renamed over PATH, and the folder synced, so a
/// reader sees the old file or the new one, never part of either. The caller makes sure PATH
/// has one writer at a time (a lock) where the last word matters; two writers at once each
/// write a whole file. False (with `error` naming the file and the problem) on failure, the
/// temporary file removed.
bool write_atomically(const std::string& path, const std::string& text, std::string& error);

/// Removes what writers of `path` killed midway left: PATH.tmp (older builds) and
/// PATH.tmp.XXXXXX in its folder. Links are removed, never followed; folders are left. Call it
/// only with PATH's lock held (no writer running).
void remove_temporaries_of(const std::string& path);

/// Whether a save could be written in `dir` now: the folder (made if missing, as a save would)
/// takes a new file, a block of text and an fsync. "" when it does, else why not, naming the
/// folder and the system's reason ("DIR: cannot save there: Read-only file system"). Nothing
/// is left behind.
std::string can_write_in(const std::string& dir);

} // namespace termpool
