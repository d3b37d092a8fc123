#pragma once
/// \file
/// What a client takes from a server, bounded: a server that sends more is broken (or not
/// ours), and the client ends the connection rather than hold without end what it is sent.
/// Each line is bounded already (max_line_bytes, and the parser bounds chat and names); these
/// bound what lines add up to: a record's text, a lobby snapshot's rows.

#include <cstddef>
#include <map>
#include <string>

#include "hall/protocol.hpp"

namespace termpool::hall {

/// The most a client takes from a server. Far above what a hall sends: its longest record
/// is 845 KB in some 5,030 lines (ServerOptions::record_allowance), its lobby at most
/// max_tables rows and max_clients players.
struct ServerBoundLimits {
    std::size_t record_bytes = 8 * 1024 * 1024;  ///< records' text being received, all tables
    std::size_t record_lines = 100000;           ///< one record's lines
    std::size_t records_at_once = 4;             ///< tables whose record is coming at once
    std::size_t lobby_tables = max_table_number; ///< table rows in one lobby snapshot
    std::size_t lobby_players = 100000;          ///< player rows in one lobby snapshot
};

/// Counts what a server sent that adds up, message by message.
class ServerBounds {
public:
    /// Bounds of `limits`.
    explicit ServerBounds(ServerBoundLimits limits = {}) : limits_(limits) {}
    /// "" while `message` keeps within the limits; otherwise what the server did wrong.
    std::string check(const ServerMessage& message);
    /// Forgets everything counted (a new connection).
    void reset();

private:
    struct Record {
        std::size_t bytes = 0;
        std::size_t lines = 0;
    };
    ServerBoundLimits limits_;
    std::map<int, Record> records_; // by table: the record coming, not ended yet
    std::size_t record_bytes_ = 0;  // all of records_
    std::size_t lobby_tables_ = 0;  // rows of the snapshot coming
    std::size_t lobby_players_ = 0;
};

} // namespace termpool::hall
