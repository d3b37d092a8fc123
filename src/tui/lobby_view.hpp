#pragma once
// What the hall's lobby shows, as plain data, and the grid it is drawn into: the tables with
// their seats, state and spectators, who is in the hall, a message and the keys. Like the
// table's View it knows no curses, so lobby frames can be built and checked without a terminal.

#include <string>
#include <vector>

#include "hall/protocol.hpp"
#include "tui/view.hpp"

namespace termpool::tui {

/// The lobby as this terminal shows it.
struct LobbyView {
    std::string name;                      ///< who sits at this terminal
    std::vector<hall::TableView> tables;   ///< in number order
    std::vector<hall::PlayerView> players; ///< everyone in the hall
    int selected = 0;                      ///< index into `tables` of the marked row
    std::string message;                   ///< news: an error, the connection's state
    std::string overlay;                   ///< a box over the lobby ('\n' between lines)
    bool connected = true;                 ///< false while the hall is away
};

/// The index into `view.tables` of the table drawn on row `y` of a `height`-row lobby, or -1
/// (a click on the list picks it).
int lobby_table_at(const LobbyView& view, int height, int y);

/// Draws the lobby into a `width` x `height` grid; at any size it writes only inside it, and
/// below 40x10 shows only "Please enlarge the terminal".
Grid render_lobby(const LobbyView& view, const Capabilities& caps, int width, int height);

} // namespace termpool::tui
