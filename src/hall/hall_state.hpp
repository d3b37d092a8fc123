#pragma once
// The hall's state folder: one file per table, rewritten atomically after every action, read
// back when the server starts again, so that no game is lost to a crash or a restart.
//
// A table's file, table-N.save, is text: a few lines of its own, then the table's record
// exactly as format_record writes it (the game's save format, see the man page, FILES):
//
//     termpool-hall-table 1
//     number 3
//     seat1-token-hash sha256 9f86d081884c7d659a2feaa0c55ad015a3bf4f1b2b0b822cd15d6c15b0f00a08
//     termpool-record 1
//     game 8-ball
//     ...
//     end
//
// The first line names the format and its version (hall_table_version; a newer version is
// refused, not misread). `number` is the table's number and must match the file's name. A
// `seatP-token-hash` line (P is 1 or 2) is there while that seat has a token: the hash of the
// token's text, SHA-256 (FIPS 180-4, hall/sha256.hpp), as 64 lowercase hex digits after the
// algorithm's name. The server hands the raw token to the player once and keeps only this
// hash, so that whoever reads the state folder still cannot take a seat: a token is 128 random
// bits, and SHA-256 cannot be turned back into one. The folder's mode 0700 keeps others out
// besides. Another algorithm's name (an older build wrote fnv1a64) is refused. Blank
// lines and `#` comments may come before the record; everything from `termpool-record` on is
// the record, and a line number in a message counts from the top of the file.

#include <string>
#include <string_view>
#include <sys/types.h>
#include <termpool/record.hpp>
#include <unistd.h>
#include <vector>

namespace termpool::hall {

/// Version of the table file's own lines, written and read by this build.
inline constexpr int hall_table_version = 1;

/// The default state folder: $XDG_STATE_HOME/termpool/hall (~/.local/state/termpool/hall).
std::string default_state_dir();

/// One table as saved: its number, the record, and each seat's token hash (empty: none).
struct SavedTable {
    int number = 0;             ///< the table's number, from 1
    GameRecord record;          ///< everything played at it
    std::string seat_tokens[2]; ///< seat_token_hash of each seat's token, "" for none
};

/// A new seat token: 32 hex digits from the kernel's random source (getrandom); empty when
/// the kernel gives none, which the caller must treat as an error.
std::string new_seat_token();

/// What the state file keeps of `token`: its SHA-256 as 64 lowercase hex digits. Compare two
/// of them with same_digest (hall/sha256.hpp), which does not stop at the first difference.
std::string seat_token_hash(std::string_view token);

/// True for text `seat_token_hash` could have made: 64 lowercase hex digits.
bool valid_seat_token_hash(std::string_view hash);

/// The path of table `number`'s file in `dir`: DIR/table-N.save.
std::string table_path(const std::string& dir, int number);

/// Writes table-N.save atomically in `dir` (made, mode 0700, if missing): the text goes to a
/// new temporary file table-N.save.tmp.XXXXXX in the same folder (write_atomically: never a
/// link or a file already there), is synced, and is renamed over the old file, so a crash
/// leaves the old file or the new one, never half of one. "" or why not, naming the
/// file and the system's reason; a number below 1 or a malformed token hash is refused.
std::string save_table(const std::string& dir, const SavedTable& table);

/// Removes table-N.save (and the temporary files a crash left, remove_temporaries_of; links
/// are removed, never followed); a missing file is no error.
void forget_table(const std::string& dir, int number);

/// Every table-N.save in `dir` that reads back (Match::replay succeeds), in number order;
/// one that does not is moved aside as table-N.save.bad (.bad.1, .bad.2, ... never over an
/// older one) and reported, appended to `problems`, as "FILE:LINE: msg (moved aside as
/// FILE.bad)"; a file that cannot be read is reported as "FILE: cannot open: strerror" and
/// moved aside too, so that a new table of that number cannot write over it, and so is one
/// over max_save_bytes ("FILE: N bytes, more than the M allowed", refused from its size) and a
/// symbolic link (the server writes none). Temporary files of table files that killed saves
/// left are removed (the caller is the folder's one server, so no save is running). Other
/// names in the folder are left alone. A missing folder holds no tables. A table file not owned
/// by `user` (this process's user unless given) is someone else's and is moved aside too.
std::vector<SavedTable> load_tables(const std::string& dir, std::vector<std::string>& problems,
                                    uid_t user = ::geteuid());

} // namespace termpool::hall
