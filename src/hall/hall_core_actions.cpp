// The hall core's game: an action checked by the table's Match on a copy, saved with the
// round's others side by side, then taken and sent; the computer's moves; aims and chat.

#include <algorithm>
#include <cstdio>

#include "hall/hall_core.hpp"

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
bool HallCore::at_action_cap(const Table& table) const {
    return table.match.record().actions.size() >= options_.max_actions;
}

// A table whose action waits for its save thinks once it is saved (action_taken).
void HallCore::think(Table& table, Clock::time_point now) {
    if (!full(table) || table.searching || table.saving || at_action_cap(table))
        return;
    const PendingAction pending = table.match.pending();
    if (pending.kind == Pending::next_rack && table.seats[pending.player - 1].computer) {
        Match next = table.match;
        if (next.next_rack(pending.player) == MatchError::none)
            propose(table, std::move(next), Proposal::From::computer_rack, 0, pending.player, now);
        return;
    }
    if (!table.match.computer_to_act())
        return;
    table.searching = true;
    table.search_ticket = table.ticket;
    pool_.submit(ComputerJob{table.number, table.ticket, table.match, std::nullopt});
}

// `next`, the table's match with one more action, is saved at the end of the round (or
// sooner, see on_message); only then does it become the table's, and the table is told. An
// action that could not be saved is not taken: were it played, a restart would lose it.
void HallCore::propose(Table& table, Match next, Proposal::From from, int client, int seat,
                       Clock::time_point now) {
    table.saving = true;
    batch_.push_back(Proposal{table.number, std::move(next), from, client, seat, now, {}});
}

// Saves the actions waiting, side by side (each save waits for the disk: a round's saves
// one after the other held every table up), then takes each one saved and tells its
// table. Nothing else happened to those tables in between: the result is as if each had
// been saved and taken at once.
void HallCore::settle(Clock::time_point now) {
    if (settling_)
        return; // settle's own loop takes what is proposed meanwhile
    settling_ = true;
    while (!batch_.empty()) {
        std::vector<Proposal> round = std::exchange(batch_, {});
        if (!options_.state_dir.empty()) {
            std::vector<SavedTable> stored;
            for (const Proposal& p : round)
                stored.push_back(saved_form(tables_.at(p.table), p.next));
            const auto start = stopwatch();
            savers_.run(round.size(), [&](std::size_t i) {
                round[i].problem = save_table(options_.state_dir, stored[i]);
            });
            saving_.add(stopwatch() - start);
        }
        for (Proposal& p : round)
            taken_or_not(p, now);
    }
    settling_ = false;
}

void HallCore::taken_or_not(Proposal& p, Clock::time_point now) {
    const auto found = tables_.find(p.table);
    if (found == tables_.end())
        return;
    Table& table = found->second;
    table.saving = false;
    if (p.problem.empty()) {
        unsaved_.erase(table.number); // the file holds the whole table as it now stands
        table.match = std::move(p.next);
        action_taken(table, now);
        handling_.add(stopwatch() - p.since);
        if (p.from == Proposal::From::computer_move)
            table.refusals = 0;
        return;
    }
    log("cannot save table " + std::to_string(table.number) + ": " + p.problem);
    switch (p.from) {
    case Proposal::From::person:
        if (const auto client = clients_.find(p.client); client != clients_.end())
            send_error(client->second, ErrorCode::internal,
                       "the action could not be saved: nothing changed, try again", now);
        break;
    case Proposal::From::computer_move:
        computer_refused(table, p.seat, "it could not be saved", now);
        break;
    case Proposal::From::computer_rack:
        log("table " + std::to_string(table.number) + ": the next rack waits");
        break;
    }
}

// The match took an action (saved): tell the table, move on.
void HallCore::action_taken(Table& table, Clock::time_point now) {
    changed(table);
    table.last_move = now;
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
        lobby_dirty_ = true;
    think(table, now);
}

void HallCore::on_sync(Client& client, const Sync& sync, Clock::time_point now) {
    Table* table = table_of(client);
    if (!table)
        return send_error(client, ErrorCode::no_table, "you are at no table", now);
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

MatchError HallCore::play(Match& match, int seat, const RecordedAction& action) {
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

void HallCore::computer_answers(std::vector<ComputerJob> answers, Clock::time_point now) {
    for (ComputerJob& answer : answers) {
        const auto found = tables_.find(answer.table);
        if (found == tables_.end() || !found->second.searching ||
            found->second.search_ticket != answer.ticket)
            continue; // a table that is gone (its number may be another table's now)
        Table& table = found->second;
        if (table.saving)
            settle(now);
        table.searching = false;
        // The table changed while the computer thought (someone left, a seat changed):
        // the answer is for a table that is no more; ask again if still the computer's turn.
        if (answer.ticket != table.ticket) {
            log("table " + std::to_string(table.number) +
                ": the computer's answer is for the table as it was: dropped");
            think(table, now);
            continue;
        }
        if (!full(table) || !table.match.computer_to_act())
            continue;
        const int seat = table.match.to_act();
        if (!answer.move) {
            computer_refused(table, seat, "it found no move", now);
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
            computer_refused(table, seat, match_error_text(error), now);
            continue;
        }
        next.reseed_computers(random_());
        propose(table, std::move(next), Proposal::From::computer_move, 0, seat, now);
    }
}

// The computer's move did not play: it searches again (with a new stream); after a few
// refusals in a row the seat is freed rather than leave the table stuck.
void HallCore::computer_refused(Table& table, int seat, const std::string& why,
                                Clock::time_point now) {
    log("table " + std::to_string(table.number) + ": the computer's move was refused: " + why);
    table.match.reseed_computers(random_());
    if (++table.refusals < 3)
        return think(table, now);
    log("table " + std::to_string(table.number) + ": seat " + std::to_string(seat) +
        " freed: its computer cannot move");
    table.refusals = 0;
    table.seats[seat - 1].computer = false;
    table.match.seat_computer(seat, std::nullopt);
    table.match.rename(seat, default_name(seat));
    save(table);
    seat_changed(table, seat);
}

void HallCore::on_act(Client& client, const RecordedAction& action, Clock::time_point now) {
    Table* table = table_of(client);
    if (!table)
        return send_error(client, ErrorCode::no_table, "you are at no table", now);
    if (client.seat == 0)
        return send_error(client, ErrorCode::not_seated, "spectators do not play", now);
    if (!full(*table))
        return send_error(client, ErrorCode::refused, "waiting for an opponent", now);
    if (!table->seats[client.seat - 1].actions.take(options_.action_rate, options_.action_burst,
                                                    now))
        return send_error(client, ErrorCode::rate, "too many actions: slow down", now);
    if (at_action_cap(*table))
        return send_error(client, ErrorCode::refused,
                          "this game has had " + std::to_string(options_.max_actions) +
                              " actions, the most a table keeps: no more are taken",
                          now);
    Match next = table->match;
    if (const MatchError error = play(next, client.seat, action); error != MatchError::none) {
        // A refused strike is told in the simulator's words (which limit, how far off).
        const auto why =
            action.kind == RecordedAction::Kind::shot && error == MatchError::bad_strike
                ? strike_problem(action.strike, table->match.game().params())
                : std::nullopt;
        return send_error(client, ErrorCode::refused, why ? *why : match_error_text(error), now);
    }
    propose(*table, std::move(next), Proposal::From::person, client.id, client.seat, now);
}

void HallCore::on_aim(Client& client, const Aim& aim, Clock::time_point now) {
    Table* table = table_of(client);
    // An aim from someone not to shoot is dropped silently: one sent just before the
    // other player's shot arrived is no fault.
    if (!table || client.seat == 0 || !full(*table) || table->match.to_act() != client.seat)
        return;
    table->seats[client.seat - 1].pending_aim = aim.strike;
    flush_aims(now);
}

// Forwards each seat's newest aim once its interval has passed.
void HallCore::flush_aims(Clock::time_point now) {
    for (auto& [number, table] : tables_)
        for (int s = 1; s <= 2; ++s) {
            SeatSlot& slot = table.seats[s - 1];
            if (!slot.pending_aim ||
                (slot.last_aim && now - *slot.last_aim < options_.aim_interval))
                continue;
            send_to_table(table, AimShown{number, s, *slot.pending_aim}, slot.client);
            slot.pending_aim.reset();
            slot.last_aim = now;
        }
}

// Milliseconds until the next aim is due, -1 for none.
int HallCore::aim_timeout(Clock::time_point now) const {
    int timeout = -1;
    for (const auto& [number, table] : tables_)
        for (const SeatSlot& slot : table.seats)
            if (slot.pending_aim && slot.last_aim) {
                const auto due = *slot.last_aim + options_.aim_interval - now;
                const int ms = static_cast<int>(std::max<long long>(
                    0, std::chrono::ceil<std::chrono::milliseconds>(due).count()));
                timeout = timeout < 0 ? ms : std::min(timeout, ms);
            }
    return timeout;
}

void HallCore::on_chat(Client& client, const Chat& chat, Clock::time_point now) {
    Table* table = table_of(client);
    if (!table)
        return send_error(client, ErrorCode::no_table, "chat is at a table", now);
    if (client.last_chat && now - *client.last_chat < options_.chat_interval)
        return send_error(client, ErrorCode::rate, "one chat line a second", now);
    client.last_chat = now;
    ChatShown line{table->number, client.name, chat.text};
    send_to_table(*table, line);
    table->chat.push_back(std::move(line));
    if (table->chat.size() > serving::chat_lines_kept)
        table->chat.pop_front();
}

} // namespace termpool::hall
