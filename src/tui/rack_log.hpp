#pragma once
// The rack's log: every shot of the current rack with its shooter, call, balls pocketed and
// the referee's verdict. It is rebuilt from the record once when a table is taken up (a resumed
// game or a table joined late has it too), then each shot adds its line as it is told.

#include <cstddef>
#include <string>
#include <termpool/match.hpp>
#include <termpool/record.hpp>
#include <vector>

namespace termpool::tui {

/// One line per shot of rack `rack` (from 1) of `record`, in order: "3. Ann: pocketed 2 5 —
/// Ann shoots again". Empty when the record does not replay.
std::vector<std::string> rack_log(const GameRecord& record, int rack);

/// Where each page of the log box starts, for `lines` on a `width` x `height` screen: as many
/// lines as fit the page's rows once wrapped as the box wraps them (a shot's line wider than
/// the box takes two rows or more), the box's border, title and footer aside. At least one page
/// (starting at 0), even for no lines.
std::vector<std::size_t> log_page_starts(const std::vector<std::string>& lines, int width,
                                         int height);

/// The log of the rack being played, kept as the shots are told.
class RackLog {
public:
    /// The shots of rack `rack` of `record` so far (one replay of the record).
    void rebuild(const GameRecord& record, int rack);
    /// A shot told, of `record`'s players; a shot of a new rack starts the rack's log afresh.
    void add(const PlayedShot& shot, const GameRecord& record);
    /// The lines of rack `rack` (none when the log is of another rack: the next has begun).
    std::vector<std::string> lines(int rack) const;

private:
    int rack_ = 0;
    std::vector<std::string> lines_;
};

} // namespace termpool::tui
