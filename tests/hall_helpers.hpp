#pragma once
// Scripted hall players for the tests: connect and say hello, wait for one kind of message,
// sit, and play the easy computer's move for whoever is to act. Every wait is bounded (kWait).

#include <catch2/catch.hpp>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <sys/socket.h>
#include <sys/un.h>
#include <termpool/match.hpp>
#include <variant>
#include <vector>

#include "hall/client.hpp"
#include "hall/hall_state.hpp"
#include "hall/unique_fd.hpp"
#include "wait_until.hpp"

namespace termpool::test {

/// The longest any one answer may take.
inline constexpr std::chrono::milliseconds kWait{5000};
/// kWait in seconds, for wait_until.
inline constexpr double kWaitSeconds = kWait.count() / 1000.0;

/// The test as the server: a socket at `path` that `client` connects to; the server's end.
inline hall::UniqueFd fake_server_for(hall::HallClient& client, const std::string& path) {
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    REQUIRE(path.size() < sizeof address.sun_path);
    std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
    const hall::UniqueFd listener(::socket(AF_UNIX, SOCK_STREAM, 0));
    REQUIRE(::bind(listener.get(), reinterpret_cast<const sockaddr*>(&address), sizeof address) ==
            0);
    REQUIRE(::listen(listener.get(), 1) == 0);
    REQUIRE(client.connect(path) == "");
    hall::UniqueFd peer(::accept(listener.get(), nullptr, nullptr));
    REQUIRE(peer);
    return peer;
}

/// True when `m` is a T.
template <class T> bool is(const hall::ServerMessage& m) {
    return std::holds_alternative<T>(m);
}

/// A client connected to `dir`/hall.sock that said hello (with `token`, or asking a new one).
inline hall::HallClient connected(const std::string& dir, const std::string& name,
                                  const std::string& token = "") {
    hall::HallClient client;
    REQUIRE(client.connect(dir + "/hall.sock") == "");
    REQUIRE(client.hello(name, token, kWait) == "");
    return client;
}

/// The next T `client` receives; the test stops when none comes in time.
template <class T> T expect(hall::HallClient& client) {
    // What came instead, for the failure's message: the variant's index of each message, and
    // the words of any error.
    std::string seen;
    const auto m = client.wait_for(
        [&](const hall::ServerMessage& message) {
            seen += " " + std::to_string(message.index());
            if (const auto* e = std::get_if<hall::Error>(&message))
                seen += "(" + e->text + ")";
            return is<T>(message);
        },
        kWait);
    INFO("waited for message kind " << hall::ServerMessage(T{}).index() << "; came:" << seen
                                    << (client.closed() ? "; closed" : ""));
    REQUIRE(m);
    return std::get<T>(*m);
}

/// A new table of `game`, on the 7 ft table; its number. The test stops on a refusal.
inline int create_table(hall::HallClient& client, GameType game = GameType::eight_ball,
                        int race_to = 1) {
    REQUIRE(client.send(hall::Create{game, TableSize::seven_foot, race_to}));
    const auto m = client.wait_for(
        [](const hall::ServerMessage& m) { return is<hall::Created>(m) || is<hall::Error>(m); },
        kWait);
    REQUIRE(m);
    if (const auto* error = std::get_if<hall::Error>(&*m))
        FAIL("create refused: " << hall::error_code_name(error->code) << " " << error->text);
    return std::get<hall::Created>(*m).table;
}

/// `client` sits at `seat` of `table` and has its record; the record's end.
inline hall::RecordEnd sit(hall::HallClient& client, int table, int seat) {
    REQUIRE(client.send(hall::Sit{table, seat}));
    const auto end = expect<hall::RecordEnd>(client);
    CHECK(end.table == table);
    REQUIRE(client.match(table));
    return end;
}

/// The move a computer of the easy level would make for whoever is to act.
inline RecordedAction chosen_move(const Match& match) {
    Match copy = match;
    copy.seat_computer(copy.to_act(), Level::easy);
    const auto move = copy.computer_move();
    REQUIRE(move);
    RecordedAction action;
    action.kind = move->kind == Pending::place    ? RecordedAction::Kind::place
                  : move->kind == Pending::choose ? RecordedAction::Kind::choose
                                                  : RecordedAction::Kind::shot;
    action.place = move->spot;
    action.choice = move->choice;
    action.strike = move->shot.strike;
    action.call = move->shot.call;
    return action;
}

/// The first of action `seq` of `table` or an error that `client` receives (within kWait).
inline std::optional<hall::ServerMessage> action_or_error(hall::HallClient& client, int table,
                                                          std::size_t seq) {
    return client.wait_for(
        [&](const hall::ServerMessage& m) {
            const auto* a = std::get_if<hall::ActionDone>(&m);
            return std::holds_alternative<hall::Error>(m) ||
                   (a && a->table == table && a->seq == seq);
        },
        kWait);
}

/// What a test that waited for action `seq` of `table` got, for its failure message.
inline std::string got_instead(const std::optional<hall::ServerMessage>& m, int table,
                               std::size_t seq) {
    return "action " + std::to_string(seq) + " of table " + std::to_string(table) + ": " +
           (m ? hall::format_server(*m) : "nothing within kWait");
}

/// Waits until `client` has seen action `seq` of `table`; an error in its place ends the wait
/// and the test, and says what it was.
inline void await_action(hall::HallClient& client, int table, std::size_t seq) {
    const auto m = action_or_error(client, table, seq);
    INFO(got_instead(m, table, seq));
    REQUIRE(m);
    REQUIRE_FALSE(std::holds_alternative<hall::Error>(*m));
}

/// Sends `move` from the seat `actor` holds at `table` and waits until the server has taken
/// it. A seat's actions have a budget (ServerOptions::action_rate a second after a burst of
/// action_burst): a test that plays a whole game at full speed can spend it (a long rack did,
/// one run in forty) and is told "rate"; it then waits a token's time (50 ms at the default 20
/// a second) and sends the move again, as a player told to slow down would.
inline void act(hall::HallClient& actor, int table, const RecordedAction& move) {
    const std::size_t seq = actor.match(table)->record().actions.size() + 1;
    // Sent again at each poll (a token's time) while the answer is "rate", until it is taken.
    const bool taken = termpool::test::wait_until(
        [&] {
            REQUIRE(actor.send(hall::Act{move}));
            const auto m = action_or_error(actor, table, seq);
            INFO(got_instead(m, table, seq));
            REQUIRE(m);
            const auto* error = std::get_if<hall::Error>(&*m);
            if (error)
                REQUIRE(error->code == hall::ErrorCode::rate);
            return error == nullptr;
        },
        kWaitSeconds, std::chrono::milliseconds(60));
    REQUIRE(taken);
}

/// The seated player to act plays one move; every client in `all` sees it.
inline void play_one(hall::HallClient& p1, hall::HallClient& p2, int table,
                     const std::vector<hall::HallClient*>& all) {
    const Match& local = *p1.match(table);
    const std::size_t seq = local.record().actions.size() + 1;
    hall::HallClient& actor = local.to_act() == 1 ? p1 : p2;
    act(actor, table, chosen_move(*actor.match(table)));
    for (hall::HallClient* client : all)
        if (client != &actor)
            await_action(*client, table, seq);
}

/// The state hash of table `table` as saved in `dir` (its record replayed).
inline std::uint64_t saved_hash(const std::string& dir, int table) {
    std::vector<std::string> problems;
    const auto tables = hall::load_tables(dir, problems);
    for (const std::string& problem : problems)
        UNSCOPED_INFO(problem);
    for (const hall::SavedTable& stored : tables)
        if (stored.number == table) {
            auto replayed = Match::replay(stored.record);
            REQUIRE(std::holds_alternative<Match>(replayed));
            return std::get<Match>(replayed).state_hash();
        }
    FAIL("table not saved");
    return 0;
}

} // namespace termpool::test
