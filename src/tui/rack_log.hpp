#pragma once
// The rack's log: every shot of the current rack with its shooter, call, balls pocketed and
// the referee's verdict, rebuilt from the record (a resumed game or a table joined late has
// it too).

#include <string>
#include <termpool/record.hpp>
#include <vector>

namespace termpool::tui {

/// One line per shot of rack `rack` (from 1) of `record`, in order: "3. Ann: pocketed 2 5 —
/// Ann shoots again". Empty when the record does not replay.
std::vector<std::string> rack_log(const GameRecord& record, int rack);

} // namespace termpool::tui
