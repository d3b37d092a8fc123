// The hall server's game: an action checked by the table's Match on a copy, saved with the
// round's others side by side, then taken and sent; the computer's moves; aims and chat.

#include <algorithm>
#include <cstdio>

#include "hall/server_state.hpp"

namespace termpool::hall {

namespace {

std::string hex_hash(std::uint64_t hash) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

} // namespace

using serving::default_name;

// After a change: a computer to act gets a search; a race whose next breaker is a computer
// racks at once (a person racks with next-rack when they are ready).
// Two seats trading fouls could grow a record without end: a table keeps so many actions.
bool Server::State::at_action_cap(const Table& table) const {
    return table.match.record().actions.size() >= options.max_actions;
}

// A table whose action waits for its save thinks once it is saved (action_taken).
void Server::State::think(Table& table) {
    if (!full(table) || table.searching || table.saving || at_action_cap(table))
        return;
    const PendingAction pending = table.match.pending();
    if (pending.kind == Pending::next_rack && table.seats[pending.player - 1].computer) {
        Match next = table.match;
        if (next.next_rack(pending.player) == MatchError::none)
            propose(table, std::move(next), Proposal::From::computer_rack, 0, pending.player);
        return;
    }
    if (!table.match.computer_to_act())
        return;
    table.searching = true;
    table.search_ticket = table.ticket;
    pool.submit(ComputerJob{table.number, table.ticket, table.match, std::nullopt});
}

// `next`, the table's match with one more action, is saved at the end of the round (or
// sooner, see on_message); only then does it become the table's, and the table is told. An
// action that could not be saved is not taken: were it played, a restart would lose it.
void Server::State::propose(Table& table, Match next, Proposal::From from, int client, int seat) {
    table.saving = true;
    batch.push_back(Proposal{table.number, std::move(next), from, client, seat, woke, {}});
}

// Saves the actions waiting, side by side (each save waits for the disk: a round's saves
// one after the other held every table up), then takes each one saved and tells its
// table. Nothing else happened to those tables in between: the result is as if each had
// been saved and taken at once.
void Server::State::settle() {
    if (settling)
        return; // settle's own loop takes what is proposed meanwhile
    settling = true;
    while (!batch.empty()) {
        std::vector<Proposal> round = std::exchange(batch, {});
        if (!options.state_dir.empty()) {
            std::vector<SavedTable> stored;
            for (const Proposal& p : round)
                stored.push_back(saved_form(tables.at(p.table), p.next));
            const auto start = Clock::now();
            savers.run(round.size(), [&](std::size_t i) {
                round[i].problem = save_table(options.state_dir, stored[i]);
            });
            saving.add(Clock::now() - start);
        }
        for (Proposal& p : round)
            taken_or_not(p);
    }
    settling = false;
}

void Server::State::taken_or_not(Proposal& p) {
    const auto found = tables.find(p.table);
    if (found == tables.end())
        return;
    Table& table = found->second;
    table.saving = false;
    if (p.problem.empty()) {
        table.match = std::move(p.next);
        action_taken(table);
        handling.add(Clock::now() - p.since);
        if (p.from == Proposal::From::computer_move)
            table.refusals = 0;
        return;
    }
    log("cannot save table " + std::to_string(table.number) + ": " + p.problem);
    switch (p.from) {
    case Proposal::From::person:
        if (const auto client = clients.find(p.client); client != clients.end())
            send_error(client->second, ErrorCode::internal,
                       "the action could not be saved: nothing changed, try again");
        break;
    case Proposal::From::computer_move:
        computer_refused(table, p.seat, "it could not be saved");
        break;
    case Proposal::From::computer_rack:
        log("table " + std::to_string(table.number) + ": the next rack waits");
        break;
    }
}

// The match took an action (saved): tell the table, move on.
void Server::State::action_taken(Table& table) {
    changed(table);
    const bool now_over = over(table);
    const auto& actions = table.match.record().actions;
    const std::uint64_t hash = table.match.state_hash();
    table.recent_hashes.emplace_back(actions.size(), hash);
    if (table.recent_hashes.size() > serving::recent_hashes_kept)
        table.recent_hashes.pop_front();
    send_to_table(table, ActionDone{table.number, actions.size(), hash, actions.back()});
    for (SeatSlot& slot : table.seats)
        slot.pending_aim.reset();
    if (now_over)
        lobby_dirty = true;
    think(table);
}

void Server::State::on_sync(Client& client, const Sync& sync) {
    Table* table = table_of(client);
    if (!table)
        return send_error(client, ErrorCode::no_table, "you are at no table");
    const std::string at = "table " + std::to_string(table->number) + ": ";
    if (!sync.seq) {
        log_repeated(client.id, "sync",
                     "client " + std::to_string(client.id) + " resynchronises table " +
                         std::to_string(table->number));
        return send_record(client, *table);
    }
    // The client's copy disagreed: what it came to, against the server's state there.
    const std::size_t held = table->match.record().actions.size();
    std::optional<std::uint64_t> ours;
    if (*sync.seq == held)
        ours = table->match.state_hash();
    for (const auto& [seq, hash] : table->recent_hashes)
        if (seq == *sync.seq)
            ours = hash;
    std::string line = at + client.name + "'s copy after action " + std::to_string(*sync.seq) +
                       " hashed " + hex_hash(sync.hash);
    if (ours && *ours == sync.hash)
        line += ", as the server's did (it could not take action " + std::to_string(*sync.seq + 1) +
                ")";
    else if (ours)
        line += ", the server's " + hex_hash(*ours);
    else if (*sync.seq > held)
        line += ", but the server holds " + std::to_string(held) + " actions";
    else
        line += ", the server's is no longer kept (it holds " + std::to_string(held) + " actions)";
    log_repeated(client.id, "sync", line + "; record sent again");
    send_record(client, *table);
}

MatchError Server::State::play(Match& match, int seat, const RecordedAction& action) {
    switch (action.kind) {
    case RecordedAction::Kind::place:
        return match.place(seat, action.place);
    case RecordedAction::Kind::choose:
        // A concession is recorded as a choice; Match::choose takes it whenever the seat is to act.
        return match.choose(seat, action.choice);
    case RecordedAction::Kind::shot: {
        const auto played = match.shoot(seat, action.strike, action.call);
        const MatchError* error = std::get_if<MatchError>(&played);
        return error ? *error : MatchError::none;
    }
    case RecordedAction::Kind::rack:
        return match.next_rack(seat);
    }
    return MatchError::not_now;
}

void Server::State::computer_answers() {
    for (ComputerJob& answer : pool.take_answers()) {
        const auto found = tables.find(answer.table);
        if (found == tables.end() || !found->second.searching ||
            found->second.search_ticket != answer.ticket)
            continue; // a table that is gone (its number may be another table's now)
        Table& table = found->second;
        if (table.saving)
            settle();
        table.searching = false;
        // The table changed while the computer thought (someone left, a seat changed):
        // the answer is for a table that is no more; ask again if still the computer's turn.
        if (answer.ticket != table.ticket) {
            log("table " + std::to_string(table.number) +
                ": the computer's answer is for the table as it was: dropped");
            think(table);
            continue;
        }
        if (!full(table) || !table.match.computer_to_act())
            continue;
        const int seat = table.match.to_act();
        if (!answer.move) {
            computer_refused(table, seat, "it found no move");
            continue;
        }
        RecordedAction action;
        action.kind = answer.move->kind == Pending::place    ? RecordedAction::Kind::place
                      : answer.move->kind == Pending::choose ? RecordedAction::Kind::choose
                                                             : RecordedAction::Kind::shot;
        action.place = answer.move->spot;
        action.choice = answer.move->choice;
        action.strike = answer.move->shot.strike;
        action.call = answer.move->shot.call;
        // Played on a copy of the live match, which stays the authority; the computers go
        // on with new streams (the one the search moved on is in the job's copy, not worth
        // carrying).
        Match next = table.match;
        if (const MatchError error = play(next, seat, action); error != MatchError::none) {
            computer_refused(table, seat, match_error_text(error));
            continue;
        }
        next.reseed_computers(random());
        propose(table, std::move(next), Proposal::From::computer_move, 0, seat);
    }
}

// The computer's move did not play: it searches again (with a new stream); after a few
// refusals in a row the seat is freed rather than leave the table stuck.
void Server::State::computer_refused(Table& table, int seat, const std::string& why) {
    log("table " + std::to_string(table.number) + ": the computer's move was refused: " + why);
    table.match.reseed_computers(random());
    if (++table.refusals < 3)
        return think(table);
    log("table " + std::to_string(table.number) + ": seat " + std::to_string(seat) +
        " freed: its computer cannot move");
    table.refusals = 0;
    table.seats[seat - 1].computer = false;
    table.match.seat_computer(seat, std::nullopt);
    table.match.rename(seat, default_name(seat));
    save(table);
    seat_changed(table, seat);
}

void Server::State::on_act(Client& client, const RecordedAction& action) {
    Table* table = table_of(client);
    if (!table)
        return send_error(client, ErrorCode::no_table, "you are at no table");
    if (client.seat == 0)
        return send_error(client, ErrorCode::not_seated, "spectators do not play");
    if (!full(*table))
        return send_error(client, ErrorCode::refused, "waiting for an opponent");
    if (!table->seats[client.seat - 1].actions.take(options.action_rate, options.action_burst,
                                                    Clock::now()))
        return send_error(client, ErrorCode::rate, "too many actions: slow down");
    if (at_action_cap(*table))
        return send_error(client, ErrorCode::refused,
                          "this game has had " + std::to_string(options.max_actions) +
                              " actions, the most a table keeps: no more are taken");
    Match next = table->match;
    if (const MatchError error = play(next, client.seat, action); error != MatchError::none) {
        // A refused strike is told in the simulator's words (which limit, how far off).
        const auto why =
            action.kind == RecordedAction::Kind::shot && error == MatchError::bad_strike
                ? strike_problem(action.strike, table->match.game().params())
                : std::nullopt;
        return send_error(client, ErrorCode::refused, why ? *why : match_error_text(error));
    }
    propose(*table, std::move(next), Proposal::From::person, client.id, client.seat);
}

void Server::State::on_aim(Client& client, const Aim& aim) {
    Table* table = table_of(client);
    // An aim from someone not to shoot is dropped silently: one sent just before the
    // other player's shot arrived is no fault.
    if (!table || client.seat == 0 || !full(*table) || table->match.to_act() != client.seat)
        return;
    table->seats[client.seat - 1].pending_aim = aim.strike;
    flush_aims(Clock::now());
}

// Forwards each seat's newest aim once its interval has passed.
void Server::State::flush_aims(Clock::time_point now) {
    for (auto& [number, table] : tables)
        for (int s = 1; s <= 2; ++s) {
            SeatSlot& slot = table.seats[s - 1];
            if (!slot.pending_aim || (slot.last_aim && now - *slot.last_aim < options.aim_interval))
                continue;
            send_to_table(table, AimShown{number, s, *slot.pending_aim}, slot.client);
            slot.pending_aim.reset();
            slot.last_aim = now;
        }
}

// Milliseconds until the next aim is due, -1 for none.
int Server::State::aim_timeout(Clock::time_point now) const {
    int timeout = -1;
    for (const auto& [number, table] : tables)
        for (const SeatSlot& slot : table.seats)
            if (slot.pending_aim && slot.last_aim) {
                const auto due = *slot.last_aim + options.aim_interval - now;
                const int ms = static_cast<int>(std::max<long long>(
                    0, std::chrono::ceil<std::chrono::milliseconds>(due).count()));
                timeout = timeout < 0 ? ms : std::min(timeout, ms);
            }
    return timeout;
}

void Server::State::on_chat(Client& client, const Chat& chat) {
    Table* table = table_of(client);
    if (!table)
        return send_error(client, ErrorCode::no_table, "chat is at a table");
    const auto now = Clock::now();
    if (client.last_chat && now - *client.last_chat < options.chat_interval)
        return send_error(client, ErrorCode::rate, "one chat line a second");
    client.last_chat = now;
    send_to_table(*table, ChatShown{table->number, client.name, chat.text});
}

} // namespace termpool::hall
