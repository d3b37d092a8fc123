// The hall core's limits on what one person may take: tables held in any state, the last free
// tables kept for people who hold none, idle connections that give way to newcomers, and
// tables everyone left, archived after archive_after without an action.

#include <algorithm>
#include <limits>

#include "hall/hall_core.hpp"
#include "hall/name_key.hpp"
#include "hall/sha256.hpp"
#include "hall/table_archive.hpp"

namespace termpool::hall {

// A table `client` holds: one not over that they created or hold a seat of (there or away),
// by their token or their name (same_name: a new token per hello gives no more tables; a new
// name per hello is a new person, kept out by the reserve below).
bool HallCore::holds(const Table& table, const Client& client) const {
    if (over(table))
        return false; // it goes when the last person leaves it
    if (same_digest(table.creator, client.token_hash) || same_name(table.creator_name, client.name))
        return true;
    for (int s = 1; s <= 2; ++s) {
        const SeatSlot& slot = table.seats[s - 1];
        if (!slot.token_hash.empty() && (same_digest(slot.token_hash, client.token_hash) ||
                                         same_name(table.match.name(s), client.name)))
            return true;
    }
    return false;
}

int HallCore::tables_held(const Client& client) const {
    return static_cast<int>(std::count_if(tables_.begin(), tables_.end(), [&](const auto& entry) {
        return holds(entry.second, client);
    }));
}

// Why `client` may not create a table now, "" when they may.
std::string HallCore::create_refusal(const Client& client) const {
    const int held = tables_held(client);
    if (held >= options_.max_tables_per_person)
        return "you hold " + serving::tables_count(static_cast<std::size_t>(held)) +
               " already, the most one person may: finish or leave one";
    const int reserve = std::min(options_.reserved_tables, (options_.max_tables + 9) / 10);
    const int free_tables = options_.max_tables - static_cast<int>(tables_.size());
    if (held > 0 && free_tables <= reserve)
        return (reserve == 1 ? std::string("the last table is")
                             : "the last " + std::to_string(reserve) + " tables are") +
               " kept for people who hold none, and you hold " + std::to_string(held);
    return {};
}

// Why `client` may not take a seat at `table`, "" when they may.
std::string HallCore::sit_refusal(const Table& table, const Client& client) const {
    if (holds(table, client))
        return {};
    const int held = tables_held(client);
    if (held >= options_.max_tables_per_person)
        return "you hold " + serving::tables_count(static_cast<std::size_t>(held)) +
               " already, the most one person may: finish or leave one";
    return {};
}

// One connection too many waits for hello: the one that has waited longest gives way (a new
// one says hello at once, a silent one has had its chance).
void HallCore::evict_for_newcomer(const Client& newcomer) {
    Client* oldest = nullptr;
    for (auto& [id, other] : clients_)
        if (id != newcomer.id && !other.welcomed && !other.closing &&
            (!oldest || other.connected_at < oldest->connected_at))
            oldest = &other;
    if (!oldest)
        return;
    log("client " + std::to_string(oldest->id) + " gave way: too many connections wait for hello");
    send_and_close(*oldest, ErrorCode::full,
                   "too many connections wait for hello: yours waited longest");
}

// The hall is full (max_clients) when someone says hello: the person idle longest in the lobby
// (at no table, nothing but pings for lobby_idle_limit) gives way; whether one did.
bool HallCore::evict_idle_lobby(const std::string& newcomer_hash, Clock::time_point now) {
    Client* idlest = nullptr;
    for (auto& [id, other] : clients_)
        if (other.welcomed && !other.closing && other.table == 0 &&
            !same_digest(other.token_hash, newcomer_hash) &&
            now - other.last_heard >= options_.lobby_idle_limit &&
            (!idlest || other.last_heard < idlest->last_heard))
            idlest = &other;
    if (!idlest)
        return false;
    log("client " + std::to_string(idlest->id) + " gave way: the hall is full, idle in the lobby");
    send_and_close(*idlest, ErrorCode::full,
                   "the hall is full and you were idle in the lobby longest: connect again to "
                   "come back");
    return true;
}

// Tables nobody is at, without an action for archive_after, are archived. Looked at no more
// often than a tenth of archive_after (at most once a minute): a day's limit needs no better.
void HallCore::archive_idle(Clock::time_point now) {
    if (next_archive_ && now < *next_archive_)
        return;
    next_archive_ =
        now + std::min<Clock::duration>(options_.archive_after / 10, std::chrono::minutes(1));
    std::vector<int> occupied;
    for (const auto& [id, client] : clients_)
        if (client.table != 0 && !client.closing)
            occupied.push_back(client.table);
    std::vector<int> due;
    for (const auto& [number, table] : tables_)
        if (now - table.last_move >= options_.archive_after &&
            std::find(occupied.begin(), occupied.end(), number) == occupied.end() &&
            !table.saving && !table.searching)
            due.push_back(number);
    for (const int number : due) {
        if (!options_.state_dir.empty()) {
            if (const std::string problem = archive_table(options_.state_dir, number);
                !problem.empty()) {
                log("cannot archive table " + std::to_string(number) + ": " + problem);
                continue; // kept: its number must not be given to a new table over its file
            }
        }
        log("table " + std::to_string(number) + " archived: nobody at it and no action for " +
            std::to_string(
                std::chrono::duration_cast<std::chrono::minutes>(options_.archive_after).count()) +
            " minutes");
        unsaved_.erase(number);
        tables_.erase(number);
        table_count_ = tables_.size();
        lobby_dirty_ = true;
    }
}

// Milliseconds until archive_idle looks again, -1 with no table.
int HallCore::archive_timeout(Clock::time_point now) const {
    if (tables_.empty())
        return -1;
    if (!next_archive_)
        return 0;
    return static_cast<int>(std::clamp<long long>(
        std::chrono::ceil<std::chrono::milliseconds>(*next_archive_ - now).count(), 0,
        std::numeric_limits<int>::max()));
}

} // namespace termpool::hall
