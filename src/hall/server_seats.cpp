// The hall server's people and seats: hello, creating a table, sitting, watching, leaving,
// away seats kept for their owners and freed in time, tables that nobody will come back to.

#include <algorithm>
#include <limits>

#include "hall/server_state.hpp"
#include "hall/sha256.hpp"

namespace termpool::hall {

using serving::default_name;

namespace {

std::variant<Match, MatchError> new_match(const Create& create, std::uint64_t seed) {
    GameRecord header;
    header.setup.game = create.game;
    // Snooker is played on the snooker table whatever size was asked for: the Match sees to
    // it (table_played), and the lobby shows the Match's table.
    header.setup.table = create.size;
    header.seed = seed;
    header.race_to = create.race_to;
    header.assist = create.assist; // in the record: both seats read it from there
    return Match::start(header, seed);
}

std::string computer_name(Level level) {
    return std::string("Computer (") + level_name(level) + ")";
}

} // namespace

void Server::State::send_record(Client& client, const Table& table) {
    const std::string text = format_record(table.match.record());
    std::string bulk; // one bulk, longer than output_limit at the action limit
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t end = text.find('\n', start);
        const std::size_t stop = end == std::string::npos ? text.size() : end;
        bulk += format_server(RecordLine{table.number, text.substr(start, stop - start)});
        start = stop + 1;
    }
    bulk += format_server(
        RecordEnd{table.number, table.match.record().actions.size(), table.match.state_hash()});
    send_bulk(client, bulk);
    for (int s = 1; s <= 2; ++s)
        send(client, SeatChange{table.number, s, seat_view(table, s)});
}

void Server::State::seat_changed(Table& table, int seat) {
    changed(table);
    send_to_table(table, SeatChange{table.number, seat, seat_view(table, seat)});
    lobby_dirty = true;
}

// Frees every away seat whose owner has been gone longer than away_limit; a table left
// with nobody goes.
void Server::State::expire_away(Clock::time_point now) {
    std::vector<int> emptied;
    for (auto& [number, table] : tables)
        for (int s = 1; s <= 2; ++s) {
            SeatSlot& slot = table.seats[s - 1];
            if (slot.token_hash.empty() || slot.client != 0 || !slot.away_since ||
                now - *slot.away_since < options.away_limit)
                continue;
            log("table " + std::to_string(number) + ": seat " + std::to_string(s) +
                " was away too long: freed");
            slot.token_hash.clear();
            slot.away_since.reset();
            table.match.rename(s, default_name(s));
            save(table);
            seat_changed(table, s);
            emptied.push_back(number);
        }
    for (const int number : emptied)
        if (auto found = tables.find(number); found != tables.end())
            forget_if_idle(found->second);
}

// Milliseconds until the next away seat is due to be freed, -1 for none.
int Server::State::away_timeout(Clock::time_point now) const {
    int timeout = -1;
    for (const auto& [number, table] : tables)
        for (const SeatSlot& slot : table.seats)
            if (!slot.token_hash.empty() && slot.client == 0 && slot.away_since) {
                const auto due = *slot.away_since + options.away_limit - now;
                const auto ms =
                    std::clamp<long long>(std::chrono::ceil<std::chrono::milliseconds>(due).count(),
                                          0, std::numeric_limits<int>::max());
                timeout =
                    timeout < 0 ? static_cast<int>(ms) : std::min(timeout, static_cast<int>(ms));
            }
    return timeout;
}

Server::State::Table* Server::State::table_of(const Client& client) {
    const auto found = tables.find(client.table);
    return found == tables.end() ? nullptr : &found->second;
}

// `client` leaves its table: by `leave` (or moving on), or because its connection dropped
// (both are the same to the seat).
// The table closes if idle, unless it is `staying` (the client moves to another seat of it).
void Server::State::leave_table(Client& client, int staying) {
    Table* table = table_of(client);
    const int seat = client.seat;
    client.table = 0;
    client.seat = 0;
    lobby_dirty = true;
    if (!table)
        return;
    if (seat != 0) {
        SeatSlot& slot = table->seats[seat - 1];
        slot.client = 0;
        slot.pending_aim.reset();
        // A seat in a game under way waits for its owner (for away_limit at most); before
        // the first action, or once the match is over, a leave or a drop frees it, so
        // that a table nobody plays at does not stay.
        if (!started(*table) || over(*table)) {
            slot.token_hash.clear();
            table->match.rename(seat, default_name(seat));
        } else {
            slot.away_since = Clock::now();
        }
        save(*table);
        seat_changed(*table, seat);
    }
    if (table->number != staying)
        forget_if_idle(*table);
}

// A table nobody is at, and nobody will come back to, goes.
void Server::State::forget_if_idle(Table& table) {
    for (const auto& [id, client] : clients)
        if (client.table == table.number && !client.closing)
            return;
    const bool away = !table.seats[0].token_hash.empty() || !table.seats[1].token_hash.empty();
    const bool computers_play = table.seats[0].computer && table.seats[1].computer;
    if (!over(table) && (away || computers_play))
        return;
    if (!options.state_dir.empty())
        forget_table(options.state_dir, table.number);
    log("table " + std::to_string(table.number) + " closed");
    tables.erase(table.number);
    table_count = tables.size();
    lobby_dirty = true;
}

void Server::State::join(Client& client, Table& table, int seat) {
    client.table = table.number;
    client.seat = seat;
    send(client, Joined{table.number, seat});
    send_record(client, table);
    lobby_dirty = true;
}

void Server::State::on_hello(Client& client, const Hello& hello) {
    if (client.welcomed)
        return send_error(client, ErrorCode::hello_first, "hello comes once");
    std::string token = hello.token.empty() ? new_seat_token() : hello.token;
    if (token.empty())
        return send_error(client, ErrorCode::internal, "no random token to give: try again");
    const std::string hash = seat_token_hash(token);
    // Only people who said hello count toward max_clients (the same person again does
    // not: their old connection gives way below).
    const auto others = std::count_if(clients.begin(), clients.end(), [&](const auto& entry) {
        const Client& other = entry.second;
        return other.welcomed && !other.closing && !same_digest(other.token_hash, hash);
    });
    if (others >= options.max_clients)
        return send_and_close(client, ErrorCode::full, "the hall has all the clients it takes");
    // The same person again: the old connection gives way (its seats go away, then the
    // new one may take them back).
    for (auto& [id, other] : clients)
        if (id != client.id && other.welcomed && same_digest(other.token_hash, hash) &&
            !other.closing) {
            send_and_close(other, ErrorCode::replaced, "you connected again elsewhere");
            leave_table(other);
        }
    client.welcomed = true;
    client.token = std::move(token);
    client.token_hash = hash;
    client.name = hello.name;
    send(client, Welcome{protocol_version, client.token});
    for (const auto& [number, table] : tables)
        for (int s = 1; s <= 2; ++s)
            if (same_digest(table.seats[s - 1].token_hash, hash) && table.seats[s - 1].client == 0)
                send(client, Yours{number, s});
    lobby_dirty = true;
    send_lobby(client, lobby_text());
}

void Server::State::on_create(Client& client, const Create& create) {
    if (static_cast<int>(tables.size()) >= options.max_tables)
        return send_error(client, ErrorCode::full, "the hall has all the tables it takes");
    const auto waiting = std::count_if(tables.begin(), tables.end(), [&](const auto& entry) {
        return same_digest(entry.second.creator, client.token_hash) && !started(entry.second);
    });
    if (waiting >= options.max_waiting_tables)
        return send_error(client, ErrorCode::full,
                          "you have " + std::to_string(waiting) + " tables waiting already");
    int number = 1;
    while (tables.count(number))
        ++number;
    if (number > max_table_number)
        return send_error(client, ErrorCode::full, "no table number is free");
    auto started_match = new_match(create, random());
    if (const MatchError* e = std::get_if<MatchError>(&started_match))
        return send_error(client, ErrorCode::refused, match_error_text(*e));
    tables.emplace(number, Table{number,
                                 std::move(std::get<Match>(started_match)),
                                 {},
                                 ++last_ticket,
                                 false,
                                 client.token_hash,
                                 0,
                                 0});
    table_count = tables.size();
    save(tables.at(number));
    send(client, Created{number});
    lobby_dirty = true;
    log("table " + std::to_string(number) + " created by " + client.name);
}

void Server::State::on_sit(Client& client, const Sit& sit) {
    const auto found = tables.find(sit.table);
    if (found == tables.end())
        return send_error(client, ErrorCode::no_table, "no such table");
    Table& table = found->second;
    SeatSlot& slot = table.seats[sit.seat - 1];
    // Sitting again where one sits changes nothing (a leave first would free the seat
    // before the first shot): the record comes again, as after a sync.
    if (client.table == sit.table && client.seat == sit.seat)
        return join(client, table, sit.seat);
    if (slot.computer ||
        (!slot.token_hash.empty() && !same_digest(slot.token_hash, client.token_hash)))
        return send_error(client, ErrorCode::seat_taken, "that seat is taken");
    if (!same_digest(slot.token_hash, client.token_hash) && over(table))
        return send_error(client, ErrorCode::refused, "the match is over");
    // One person holds one seat of a table: the other seat stays theirs unless they sit in
    // it now and a leave frees it (before the first action).
    const SeatSlot& other = table.seats[2 - sit.seat];
    const bool moving_over =
        client.table == sit.table && client.seat == 3 - sit.seat && !started(table) && !over(table);
    if (same_digest(other.token_hash, client.token_hash) && !moving_over)
        return send_error(client, ErrorCode::refused, "you hold the other seat of this table");
    if (client.table != 0)
        leave_table(client, sit.table); // never closes this table
    const bool mine = same_digest(slot.token_hash, client.token_hash);
    slot.client = client.id;
    slot.away_since.reset();
    if (!mine) {
        slot.token_hash = client.token_hash;
        table.match.rename(sit.seat, client.name);
    }
    save(table);
    join(client, table, sit.seat);
    seat_changed(table, sit.seat);
    think(table);
}

void Server::State::on_watch(Client& client, const Watch& watch) {
    if (!tables.count(watch.table))
        return send_error(client, ErrorCode::no_table, "no such table");
    if (client.table != 0)
        leave_table(client, watch.table);
    join(client, tables.at(watch.table), 0);
}

void Server::State::on_computer(Client& client, const SeatComputer& request) {
    Table* table = table_of(client);
    if (!table)
        return send_error(client, ErrorCode::no_table, "you are at no table");
    // The players choose their opponent; a spectator must not change the game.
    if (client.seat == 0)
        return send_error(client, ErrorCode::not_seated,
                          "only a player seated here seats the computer");
    SeatSlot& slot = table->seats[request.seat - 1];
    if (!slot.token_hash.empty() || (slot.computer && request.level && started(*table)))
        return send_error(client, ErrorCode::seat_taken, "that seat is taken");
    if (!request.level && (!slot.computer || started(*table)))
        return send_error(client, ErrorCode::refused, "no computer to unseat");
    if (over(*table))
        return send_error(client, ErrorCode::refused, "the match is over");
    table->match.seat_computer(request.seat, request.level);
    table->match.rename(request.seat,
                        request.level ? computer_name(*request.level) : default_name(request.seat));
    slot.computer = request.level.has_value();
    save(*table);
    seat_changed(*table, request.seat);
    think(*table);
}

// A creator gone (and not connected again elsewhere) takes the tables they made and
// nobody came to: a table not started, nobody at it.
void Server::State::forget_waiting_tables_of(const std::string& token_hash) {
    if (token_hash.empty())
        return;
    for (const auto& [id, client] : clients)
        if (same_digest(client.token_hash, token_hash) && !client.closing)
            return;
    std::vector<int> numbers;
    for (const auto& [number, table] : tables)
        if (same_digest(table.creator, token_hash) && !started(table))
            numbers.push_back(number);
    for (const int number : numbers)
        forget_if_idle(tables.at(number));
}

} // namespace termpool::hall
