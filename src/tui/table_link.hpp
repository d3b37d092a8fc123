#pragma once
// A table played in the hall: the server owns the match, so the App sends what the player at
// this terminal does and plays what the server applied, in the server's order. The hall
// session fills in where the words go (the socket); the App never sees the protocol.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <termpool/record.hpp>
#include <termpool/simulator.hpp>

namespace termpool::tui {

/// Where a hall table's App sends what happens at this terminal.
struct TableLink {
    int seat = 0; ///< the seat this terminal plays, 1 or 2; 0 watches
    /// A place, shot or choose action of this seat, or a rack action for the next rack; the
    /// App waits for the server to apply it (`App::hall_action`) or refuse it.
    std::function<void(const RecordedAction&)> act;
    /// The cue as this seat aims (the session keeps to the server's rate).
    std::function<void(const Strike&)> aim;
    /// A chat line typed at this terminal (already checked: 1 to 200 characters, printable);
    /// false when it cannot go yet (one line a second), and the line stays to be sent again.
    std::function<bool(const std::string&)> chat;
};

/// Where this terminal's copy of a hall table stood when it parted from the server's: for the
/// server's log.
struct CopyState {
    std::size_t actions = 0; ///< actions the copy holds
    std::uint64_t hash = 0;  ///< its state hash
};

/// A seat at a hall table as the panel shows it.
struct HallSeat {
    std::string name;      ///< who sits there ("" for an empty seat)
    bool away = false;     ///< a person whose connection dropped: the table waits for them
    bool empty = false;    ///< nobody yet
    bool computer = false; ///< the server plays it
};

} // namespace termpool::tui
