#pragma once
/// \file
/// Tables the hall no longer holds but keeps as files: a table everyone left, with no action
/// for a day, moves out of the state folder into its archive/ subfolder, so that it leaves the
/// lobby (and frees its number) while its game can still be read.

#include <string>

namespace termpool::hall {

/// Moves table `number`'s file (table_path) into `dir`/archive/ (made, mode 0700, if missing)
/// as table-N.save, or table-N.save.1, .2, ... when that name is taken: never over another
/// file. "" or why not (the file then stays where it was). A missing file is no error.
std::string archive_table(const std::string& dir, int number);

} // namespace termpool::hall
