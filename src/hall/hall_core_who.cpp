// The hall core's answer to `who`: what a host's admin needs to see of a running hall (its
// tables, the people at them, the connections) without reading its log. Never a token or a
// token's hash: whoever asks sees what the lobby shows, and how long people have been here.

#include <cstdio>
#include <map>
#include <termpool/game_registry.hpp>

#include "hall/hall_core.hpp"

namespace termpool::hall {

namespace {

// A duration as a person reads it: "45 s", "12 min", "3 h 05 min", "2 d 4 h".
std::string span_words(std::chrono::steady_clock::duration span) {
    const long long s =
        std::max<long long>(0, std::chrono::duration_cast<std::chrono::seconds>(span).count());
    char text[40];
    if (s < 60)
        std::snprintf(text, sizeof text, "%lld s", s);
    else if (s < 3600)
        std::snprintf(text, sizeof text, "%lld min", s / 60);
    else if (s < 86400)
        std::snprintf(text, sizeof text, "%lld h %02lld min", s / 3600, s / 60 % 60);
    else
        std::snprintf(text, sizeof text, "%lld d %lld h", s / 86400, s / 3600 % 24);
    return text;
}

} // namespace

std::vector<std::string> HallCore::who_lines(int asker, Clock::time_point now) const {
    std::map<int, int> spectators; // by table
    int welcomed = 0;
    std::size_t others = 0; // connections not past hello, the asker's aside
    for (const auto& [id, client] : clients_) {
        welcomed += client.welcomed ? 1 : 0;
        others += !client.welcomed && id != asker ? 1 : 0;
        if (client.table != 0 && client.seat == 0)
            ++spectators[client.table];
    }
    std::vector<std::string> lines;
    lines.push_back("hall: " + std::to_string(welcomed) + " of " +
                    std::to_string(options_.max_clients) + " people, " + std::to_string(others) +
                    " connections waiting for hello, " + std::to_string(tables_.size()) + " of " +
                    std::to_string(options_.max_tables) + " tables");
    for (const auto& [number, table] : tables_) {
        const auto found = spectators.find(number);
        const TableView view = table_view(table, found == spectators.end() ? 0 : found->second);
        std::string line = "table " + std::to_string(number) + ": " + game_row(view.game).title +
                           ", race to " + std::to_string(view.race_to) + ", " +
                           table_state_name(view.state) + ", " +
                           std::to_string(table.match.record().actions.size()) + " actions;";
        for (int s = 0; s < 2; ++s) {
            const SeatView& seat = view.seats[s];
            line += " seat " + std::to_string(s + 1) + " " + seat_kind_name(seat.kind);
            if (seat.kind != SeatKind::empty)
                line += " " + seat.name;
            if (seat.kind == SeatKind::away && table.seats[s].away_since)
                line += " for " + span_words(now - *table.seats[s].away_since);
            line += ",";
        }
        line += " " + std::to_string(view.spectators) + " watching";
        lines.push_back(line);
    }
    for (const auto& [id, client] : clients_) {
        std::string line = "connection " + std::to_string(id) + ": ";
        if (id == asker)
            line += "this question";
        else if (!client.welcomed)
            line += "no hello yet";
        else if (client.table == 0)
            line += client.name + " in the lobby";
        else
            line += client.name + " at table " + std::to_string(client.table) +
                    (client.seat == 0 ? " watching" : " in seat " + std::to_string(client.seat));
        line += ", connected " + span_words(now - client.connected_at) + ", " +
                std::to_string(queued(id)) + " bytes to send";
        lines.push_back(line);
    }
    return lines;
}

} // namespace termpool::hall
