// The hall core's people and seats: hello, creating a table, sitting, watching, leaving,
// away seats kept for their owners and freed in time, tables that nobody will come back to.

#include <algorithm>
#include <limits>

#include "hall/hall_core.hpp"
#include "hall/name_key.hpp"
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

void HallCore::send_record(Client& client, const Table& table) {
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

void HallCore::seat_changed(Table& table, int seat) {
    changed(table);
    send_to_table(table, SeatChange{table.number, seat, seat_view(table, seat)});
    lobby_dirty_ = true;
}

// Frees every away seat whose owner has been gone longer than away_limit; a table left
// with nobody goes.
void HallCore::expire_away(Clock::time_point now) {
    std::vector<int> emptied;
    for (auto& [number, table] : tables_)
        for (int s = 1; s <= 2; ++s) {
            SeatSlot& slot = table.seats[s - 1];
            if (slot.token_hash.empty() || slot.client != 0 || !slot.away_since ||
                now - *slot.away_since < options_.away_limit)
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
        if (auto found = tables_.find(number); found != tables_.end())
            forget_if_idle(found->second);
}

// Milliseconds until the next away seat is due to be freed, -1 for none.
int HallCore::away_timeout(Clock::time_point now) const {
    int timeout = -1;
    for (const auto& [number, table] : tables_)
        for (const SeatSlot& slot : table.seats)
            if (!slot.token_hash.empty() && slot.client == 0 && slot.away_since) {
                const auto due = *slot.away_since + options_.away_limit - now;
                const auto ms =
                    std::clamp<long long>(std::chrono::ceil<std::chrono::milliseconds>(due).count(),
                                          0, std::numeric_limits<int>::max());
                timeout =
                    timeout < 0 ? static_cast<int>(ms) : std::min(timeout, static_cast<int>(ms));
            }
    return timeout;
}

HallCore::Table* HallCore::table_of(const Client& client) {
    const auto found = tables_.find(client.table);
    return found == tables_.end() ? nullptr : &found->second;
}

// `client` leaves its table: by `leave` (or moving on), or because its connection dropped
// (both are the same to the seat).
// The table closes if idle, unless it is `staying` (the client moves to another seat of it).
void HallCore::leave_table(Client& client, Clock::time_point now, int staying) {
    Table* table = table_of(client);
    const int seat = client.seat;
    client.table = 0;
    client.seat = 0;
    lobby_dirty_ = true;
    if (!table)
        return;
    if (seat != 0) {
        SeatSlot& slot = table->seats[seat - 1];
        slot.client = 0;
        slot.pending_aim.reset();
        // A seat in a game under way waits for its owner (for away_limit at most); before
        // the first action, or once the match is over, a leave or a drop frees it, so
        // that a table nobody plays at does not stay.
        if (!table->match.under_way()) {
            slot.token_hash.clear();
            table->match.rename(seat, default_name(seat));
        } else {
            slot.away_since = now;
        }
        save(*table);
        seat_changed(*table, seat);
    }
    if (table->number != staying)
        forget_if_idle(*table);
}

// A table nobody is at, and nobody will come back to, goes.
void HallCore::forget_if_idle(Table& table) {
    for (const auto& [id, client] : clients_)
        if (client.table == table.number && !client.closing)
            return;
    const bool away = !table.seats[0].token_hash.empty() || !table.seats[1].token_hash.empty();
    const bool computers_play = table.seats[0].computer && table.seats[1].computer;
    if (!over(table) && (away || computers_play))
        return;
    if (!options_.state_dir.empty())
        forget_table(options_.state_dir, table.number);
    log("table " + std::to_string(table.number) + " closed");
    unsaved_.erase(table.number);
    tables_.erase(table.number);
    table_count_ = tables_.size();
    lobby_dirty_ = true;
}

void HallCore::join(Client& client, Table& table, int seat) {
    client.table = table.number;
    client.seat = seat;
    send(client, Joined{table.number, seat});
    send_record(client, table);
    for (const ChatShown& line : table.chat)
        send(client, line);
    lobby_dirty_ = true;
}

void HallCore::on_hello(Client& client, const Hello& hello, Clock::time_point now) {
    if (client.welcomed)
        return send_error(client, ErrorCode::hello_first, "hello comes once", now);
    std::string token = hello.token.empty() ? new_seat_token() : hello.token;
    if (token.empty())
        return send_error(client, ErrorCode::internal, "no random token to give: try again", now);
    const std::string hash = seat_token_hash(token);
    // Only people who said hello count toward max_clients (the same person again does
    // not: their old connection gives way below).
    const auto others = std::count_if(clients_.begin(), clients_.end(), [&](const auto& entry) {
        const Client& other = entry.second;
        return other.welcomed && !other.closing && !same_digest(other.token_hash, hash);
    });
    // One name, one person: another person (another token) in the hall under the same name,
    // however typed (name_key), would make the lobby and the tables say "Ann" of two people.
    const std::string key = name_key(hello.name);
    for (const auto& [id, other] : clients_)
        if (id != client.id && other.welcomed && !other.closing &&
            !same_digest(other.token_hash, hash) && name_key(other.name) == key)
            return send_and_close(client, ErrorCode::name_taken,
                                  "someone in the hall is called " + other.name +
                                      " already: come in under another name");
    // A seat held by a token keeps the name it shows while its owner is away (until the away
    // limit, or archive_after for a table nobody is at), so that no one else can take the name
    // and keep the owner out when they come back with their token: under --name they can come
    // in under no other. A token that holds a seat showing the name itself comes in: a state
    // folder from before this rule may hold the name at seats of two tokens.
    const Table* taken_at = nullptr;
    int taken_seat = 0;
    bool own_seat = false;
    for (const auto& [number, table] : tables_)
        for (int s = 1; s <= 2; ++s) {
            const SeatSlot& slot = table.seats[s - 1];
            if (slot.token_hash.empty() || !same_name(table.match.name(s), hello.name))
                continue;
            if (same_digest(slot.token_hash, hash)) {
                own_seat = true;
            } else if (!taken_at) {
                taken_at = &table;
                taken_seat = s;
            }
        }
    if (taken_at && !own_seat) {
        const std::string& shown = taken_at->match.name(taken_seat);
        // The client keeps a token under the name exactly as typed: the owner finds theirs
        // under that spelling.
        return send_and_close(client, ErrorCode::name_taken,
                              shown + " holds a seat at table " + std::to_string(taken_at->number) +
                                  ": if it is yours, come in as " + shown +
                                  " exactly; if not, under another name");
    }
    if (others >= options_.max_clients && !evict_idle_lobby(hash, now))
        return send_and_close(client, ErrorCode::full, "the hall has all the clients it takes");
    // The same person again: the old connection gives way (its seats go away, then the
    // new one may take them back).
    for (auto& [id, other] : clients_)
        if (id != client.id && other.welcomed && same_digest(other.token_hash, hash) &&
            !other.closing) {
            send_and_close(other, ErrorCode::replaced, "you connected again elsewhere");
            leave_table(other, now);
        }
    client.welcomed = true;
    client.token = std::move(token);
    client.token_hash = hash;
    client.name = hello.name;
    send(client, Welcome{protocol_version, client.token});
    for (const auto& [number, table] : tables_)
        for (int s = 1; s <= 2; ++s)
            if (same_digest(table.seats[s - 1].token_hash, hash) && table.seats[s - 1].client == 0)
                send(client, Yours{number, s});
    lobby_dirty_ = true;
    send_text(client, lobby_text());
}

void HallCore::on_create(Client& client, const Create& create, Clock::time_point now) {
    if (static_cast<int>(tables_.size()) >= options_.max_tables)
        return send_error(client, ErrorCode::full, "the hall has all the tables it takes", now);
    const auto waiting = std::count_if(tables_.begin(), tables_.end(), [&](const auto& entry) {
        return same_digest(entry.second.creator, client.token_hash) && !started(entry.second);
    });
    if (waiting >= options_.max_waiting_tables)
        return send_error(client, ErrorCode::full,
                          "you have " + std::to_string(waiting) + " tables waiting already", now);
    if (const std::string why = create_refusal(client); !why.empty())
        return send_error(client, ErrorCode::full, why, now);
    int number = 1;
    while (tables_.count(number))
        ++number;
    if (number > max_table_number)
        return send_error(client, ErrorCode::full, "no table number is free", now);
    auto started_match = new_match(create, random_());
    if (const MatchError* e = std::get_if<MatchError>(&started_match))
        return send_error(client, ErrorCode::refused, match_error_text(*e), now);
    tables_.emplace(number, Table{number,
                                  std::move(std::get<Match>(started_match)),
                                  {},
                                  ++last_ticket_,
                                  false,
                                  client.token_hash,
                                  0,
                                  0});
    tables_.at(number).creator_name = client.name;
    tables_.at(number).last_move = now;
    table_count_ = tables_.size();
    // A table that cannot be saved could never be played (every action is saved before it is
    // taken): it is not made, and the player is told why.
    if (const std::string problem = save(tables_.at(number)); !problem.empty()) {
        unsaved_.erase(number);
        tables_.erase(number);
        table_count_ = tables_.size();
        return send_error(client, ErrorCode::internal,
                          "the hall cannot save tables (" +
                              problem.substr(problem.rfind(": ") == std::string::npos
                                                 ? 0
                                                 : problem.rfind(": ") + 2) +
                              "): no table was made; tell the hall's host",
                          now);
    }
    send(client, Created{number});
    lobby_dirty_ = true;
    log("table " + std::to_string(number) + " created by " + client.name);
}

void HallCore::on_sit(Client& client, const Sit& sit, Clock::time_point now) {
    const auto found = tables_.find(sit.table);
    if (found == tables_.end())
        return send_error(client, ErrorCode::no_table, "no such table", now);
    Table& table = found->second;
    SeatSlot& slot = table.seats[sit.seat - 1];
    // Sitting again where one sits changes nothing (a leave first would free the seat
    // before the first shot): the record comes again, as after a sync.
    if (client.table == sit.table && client.seat == sit.seat)
        return join(client, table, sit.seat);
    if (slot.computer ||
        (!slot.token_hash.empty() && !same_digest(slot.token_hash, client.token_hash)))
        return send_error(client, ErrorCode::seat_taken, "that seat is taken", now);
    if (!same_digest(slot.token_hash, client.token_hash) && over(table))
        return send_error(client, ErrorCode::refused, "the match is over", now);
    // One person holds one seat of a table: the other seat stays theirs unless they sit in
    // it now and a leave frees it (before the first action).
    const SeatSlot& other = table.seats[2 - sit.seat];
    const bool moving_over =
        client.table == sit.table && client.seat == 3 - sit.seat && !started(table) && !over(table);
    if (same_digest(other.token_hash, client.token_hash) && !moving_over)
        return send_error(client, ErrorCode::refused, "you hold the other seat of this table", now);
    if (const std::string why = sit_refusal(table, client); !why.empty())
        return send_error(client, ErrorCode::full, why, now);
    if (client.table != 0)
        leave_table(client, now, sit.table); // never closes this table
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
    think(table, now);
}

void HallCore::on_watch(Client& client, const Watch& watch, Clock::time_point now) {
    if (!tables_.count(watch.table))
        return send_error(client, ErrorCode::no_table, "no such table", now);
    if (client.table != 0)
        leave_table(client, now, watch.table);
    join(client, tables_.at(watch.table), 0);
}

void HallCore::on_computer(Client& client, const SeatComputer& request, Clock::time_point now) {
    Table* table = table_of(client);
    if (!table)
        return send_error(client, ErrorCode::no_table, "you are at no table", now);
    // The players choose their opponent; a spectator must not change the game.
    if (client.seat == 0)
        return send_error(client, ErrorCode::not_seated,
                          "only a player seated here seats the computer", now);
    SeatSlot& slot = table->seats[request.seat - 1];
    if (!slot.token_hash.empty() || (slot.computer && request.level && started(*table)))
        return send_error(client, ErrorCode::seat_taken, "that seat is taken", now);
    if (!request.level && (!slot.computer || started(*table)))
        return send_error(client, ErrorCode::refused, "no computer to unseat", now);
    if (over(*table))
        return send_error(client, ErrorCode::refused, "the match is over", now);
    table->match.seat_computer(request.seat, request.level);
    table->match.rename(request.seat,
                        request.level ? computer_name(*request.level) : default_name(request.seat));
    slot.computer = request.level.has_value();
    save(*table);
    seat_changed(*table, request.seat);
    think(*table, now);
}

// A creator gone (and not connected again elsewhere) takes the tables they made and
// nobody came to: a table not started, nobody at it.
void HallCore::forget_waiting_tables_of(const std::string& token_hash) {
    if (token_hash.empty())
        return;
    for (const auto& [id, client] : clients_)
        if (same_digest(client.token_hash, token_hash) && !client.closing)
            return;
    std::vector<int> numbers;
    for (const auto& [number, table] : tables_)
        if (same_digest(table.creator, token_hash) && !started(table))
            numbers.push_back(number);
    for (const int number : numbers)
        forget_if_idle(tables_.at(number));
}

} // namespace termpool::hall
