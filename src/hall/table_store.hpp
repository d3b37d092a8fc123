#pragma once
/// \file
/// Where the server keeps its tables between runs. A stand-in with the shape of hall_state's
/// API (HALL.md: save_table, forget_table, load_tables), so that the server does not wait
/// for it: once hall_state is merged, these three functions call it and this file's format
/// goes away.
///
/// The format here: `table-N.save` in the state folder: two lines `# seat1-token HASH|-` and
/// `# seat2-token HASH|-`, then the record's text.

#include <string>
#include <termpool/record.hpp>
#include <vector>

namespace termpool::hall {

/// One table as kept: its number, its record, and each seat's token hash (empty: none).
struct StoredTable {
    int number = 0;             ///< 1 to max_table_number
    GameRecord record;          ///< everything played
    std::string seat_tokens[2]; ///< token_hash of each seat's owner, empty for none
};

/// Writes table-N.save atomically (temporary file, fsync, rename) in `dir`; "" or why not.
std::string store_table(const std::string& dir, const StoredTable& table);

/// Removes table-N.save from `dir`.
void drop_stored_table(const std::string& dir, int number);

/// Every table-N.save in `dir` that reads back, in number order; each one that does not is
/// reported in `problems` as "FILE: why".
std::vector<StoredTable> load_stored_tables(const std::string& dir,
                                            std::vector<std::string>& problems);

} // namespace termpool::hall
