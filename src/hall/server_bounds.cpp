#include "hall/server_bounds.hpp"

#include <variant>

namespace termpool::hall {

std::string ServerBounds::check(const ServerMessage& message) {
    if (const auto* m = std::get_if<RecordLine>(&message)) {
        if (!records_.count(m->table) && records_.size() >= limits_.records_at_once)
            return "records of more than " + std::to_string(limits_.records_at_once) +
                   " tables at once";
        Record& record = records_[m->table];
        record.bytes += m->text.size() + 1;
        record_bytes_ += m->text.size() + 1;
        if (++record.lines > limits_.record_lines)
            return "a record of more than " + std::to_string(limits_.record_lines) + " lines";
        if (record_bytes_ > limits_.record_bytes)
            return "records of more than " + std::to_string(limits_.record_bytes) + " bytes";
    } else if (const auto* m = std::get_if<RecordEnd>(&message)) {
        if (const auto found = records_.find(m->table); found != records_.end()) {
            record_bytes_ -= found->second.bytes;
            records_.erase(found);
        }
    } else if (std::holds_alternative<LobbyBegin>(message) ||
               std::holds_alternative<LobbyEnd>(message)) {
        lobby_tables_ = lobby_players_ = 0;
    } else if (std::holds_alternative<TableView>(message)) {
        if (++lobby_tables_ > limits_.lobby_tables)
            return "a lobby of more than " + std::to_string(limits_.lobby_tables) + " tables";
    } else if (std::holds_alternative<PlayerView>(message)) {
        if (++lobby_players_ > limits_.lobby_players)
            return "a lobby of more than " + std::to_string(limits_.lobby_players) + " players";
    }
    return {};
}

void ServerBounds::reset() {
    records_.clear();
    record_bytes_ = lobby_tables_ = lobby_players_ = 0;
}

} // namespace termpool::hall
