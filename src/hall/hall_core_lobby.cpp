// The hall core's lobby: the snapshot of every table and person, made once for everyone
// it goes to, at most every lobby_interval.

#include <algorithm>

#include "hall/hall_core.hpp"

namespace termpool::hall {

SeatView HallCore::seat_view(const Table& table, int seat) const {
    const SeatSlot& slot = table.seats[seat - 1];
    if (slot.computer)
        return {SeatKind::computer, table.match.name(seat)};
    if (slot.token_hash.empty())
        return {SeatKind::empty, ""};
    return {slot.client != 0 ? SeatKind::player : SeatKind::away, table.match.name(seat)};
}

TableView HallCore::table_view(const Table& table, int spectators) const {
    TableView view;
    view.number = table.number;
    view.game = table.match.setup().game;
    view.size = table.match.setup().table;
    view.race_to = std::max(1, table.match.record().race_to);
    view.assist = table.match.record().assist;
    view.state = over(table)   ? TableState::over
                 : full(table) ? TableState::playing
                               : TableState::waiting;
    for (int s = 1; s <= 2; ++s)
        view.seats[s - 1] = seat_view(table, s);
    view.spectators = spectators;
    return view;
}

// The whole lobby as it goes out, made once for everyone it goes to: with a few hundred
// people and a hundred tables, a snapshot made per client (each table counting its
// spectators among all clients) stalled the loop for tens of milliseconds.
std::string HallCore::lobby_text() const {
    std::map<int, int> spectators; // by table
    for (const auto& [id, client] : clients_)
        if (client.table != 0 && client.seat == 0)
            ++spectators[client.table];
    std::string text = format_server(LobbyBegin{});
    for (const auto& [number, table] : tables_) {
        const auto found = spectators.find(number);
        text += format_server(table_view(table, found == spectators.end() ? 0 : found->second));
    }
    for (const auto& [id, other] : clients_)
        if (other.welcomed && !other.closing)
            text += format_server(PlayerView{other.name, other.table, other.seat});
    return text + format_server(LobbyEnd{});
}

// The lobby's changes go out as one snapshot at most every lobby_interval; a client whose
// output still holds more than lobby_queue_limit bytes gets it once it has read them.
void HallCore::send_lobbies(Clock::time_point now) {
    if (lobby_dirty_ && (!last_lobby_ || now - *last_lobby_ >= options_.lobby_interval)) {
        lobby_dirty_ = false;
        last_lobby_ = now;
        for (auto& [id, client] : clients_)
            client.lobby_owed = client.welcomed;
    }
    std::optional<std::string> text; // made once, when the first client is due one
    for (auto& [id, client] : clients_)
        if (client.lobby_owed && !client.closing && queued(id) <= options_.lobby_queue_limit) {
            client.lobby_owed = false;
            if (!text)
                text = lobby_text();
            send_text(client, *text);
        }
}

// Milliseconds until a lobby snapshot is due, -1 for none.
int HallCore::lobby_timeout(Clock::time_point now) const {
    for (const auto& [id, client] : clients_)
        if (client.lobby_owed && !client.closing && queued(id) <= options_.lobby_queue_limit)
            return 0;
    if (!lobby_dirty_)
        return -1;
    if (!last_lobby_)
        return 0;
    const auto due = *last_lobby_ + options_.lobby_interval - now;
    return static_cast<int>(
        std::max<long long>(0, std::chrono::ceil<std::chrono::milliseconds>(due).count()));
}

} // namespace termpool::hall
