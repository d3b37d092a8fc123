// The hall server's lobby: the snapshot of every table and person, made once for everyone
// it goes to, at most every lobby_interval.

#include <algorithm>

#include "hall/server_state.hpp"

namespace termpool::hall {

SeatView Server::State::seat_view(const Table& table, int seat) const {
    const SeatSlot& slot = table.seats[seat - 1];
    if (slot.computer)
        return {SeatKind::computer, table.match.name(seat)};
    if (slot.token_hash.empty())
        return {SeatKind::empty, ""};
    return {slot.client != 0 ? SeatKind::player : SeatKind::away, table.match.name(seat)};
}

TableView Server::State::table_view(const Table& table, int spectators) const {
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
std::string Server::State::lobby_text() const {
    std::map<int, int> spectators; // by table
    for (const auto& [id, client] : clients)
        if (client.table != 0 && client.seat == 0)
            ++spectators[client.table];
    std::string text = format_server(LobbyBegin{});
    for (const auto& [number, table] : tables) {
        const auto found = spectators.find(number);
        text += format_server(table_view(table, found == spectators.end() ? 0 : found->second));
    }
    for (const auto& [id, other] : clients)
        if (other.welcomed && !other.closing)
            text += format_server(PlayerView{other.name, other.table, other.seat});
    return text + format_server(LobbyEnd{});
}

void Server::State::send_lobby(Client& client, const std::string& text) {
    if (client.closing)
        return;
    if (!client.connection.queue(text, options.output_limit)) {
        log("client " + std::to_string(client.id) + " stopped reading: disconnected");
        client.closing = true;
    }
}

// The lobby's changes go out as one snapshot at most every lobby_interval; a client whose
// output still holds more than lobby_queue_limit bytes gets it once it has read them.
void Server::State::send_lobbies(Clock::time_point now) {
    if (lobby_dirty && (!last_lobby || now - *last_lobby >= options.lobby_interval)) {
        lobby_dirty = false;
        last_lobby = now;
        for (auto& [id, client] : clients)
            client.lobby_owed = client.welcomed;
    }
    std::optional<std::string> text; // made once, when the first client is due one
    for (auto& [id, client] : clients)
        if (client.lobby_owed && !client.closing &&
            client.connection.queued() <= options.lobby_queue_limit) {
            client.lobby_owed = false;
            if (!text)
                text = lobby_text();
            send_lobby(client, *text);
        }
}

// Milliseconds until a lobby snapshot is due, -1 for none.
int Server::State::lobby_timeout(Clock::time_point now) const {
    for (const auto& [id, client] : clients)
        if (client.lobby_owed && !client.closing &&
            client.connection.queued() <= options.lobby_queue_limit)
            return 0;
    if (!lobby_dirty)
        return -1;
    if (!last_lobby)
        return 0;
    const auto due = *last_lobby + options.lobby_interval - now;
    return static_cast<int>(
        std::max<long long>(0, std::chrono::ceil<std::chrono::milliseconds>(due).count()));
}

} // namespace termpool::hall
