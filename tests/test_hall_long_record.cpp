// A table whose record is as long as the hall keeps is joined and watched again: its record,
// far over the output queue's bound, reaches a client that reads at full speed. The
// connection's bulk allowance that lets it, tested on its own.
#include "support/text_numbers.hpp"
#include <catch2/catch.hpp>
#include <string>
#include <sys/socket.h>

#include "hall/client.hpp"
#include "hall/connection.hpp"
#include "hall/hall_state.hpp"
#include "hall/protocol.hpp"
#include "hall/server.hpp"
#include "hall_helpers.hpp"
#include "long_record.hpp"
#include "server_thread.hpp"
#include "temp_dir.hpp"

using namespace termpool;
using namespace termpool::hall;
using namespace termpool::test;

namespace {

const std::string ann_token = "0123456789abcdef0123456789abcdef";
const std::string bob_token = "fedcba9876543210fedcba9876543210";

} // namespace

TEST_CASE("hall: a table at the action limit is joined and watched, its whole record sent",
          "[hall]") {
    const ServerOptions defaults;
    const GameRecord record = long_eight_ball_record(defaults.max_actions);
    const std::string text = format_record(record);
    // Far over the queue's bound: sent at once, it would cut off every reader.
    INFO("the record: " << text.size() << " bytes");
    REQUIRE(text.size() > 2 * defaults.output_limit);
    test::TempDir dir("termpool-hall");
    REQUIRE(save_table(
                dir.path(),
                SavedTable{1, record, {seat_token_hash(ann_token), seat_token_hash(bob_token)}}) ==
            "");
    ServerThread running(dir.path(), defaults);

    HallClient eve = connected(dir.path(), "Eve");
    REQUIRE(eve.send(Watch{1}));
    HallClient ann = connected(dir.path(), "Ann", ann_token);
    REQUIRE(ann.send(Sit{1, 1}));
    for (HallClient* client : {&eve, &ann}) {
        const RecordEnd end = expect<RecordEnd>(*client);
        CHECK(end.seq == record.actions.size());
        REQUIRE(client->match(1));
        CHECK(client->match(1)->record().actions.size() == record.actions.size());
        CHECK(client->mismatches() == 0);
        CHECK_FALSE(client->closed());
    }
    // Still served: a ping is answered.
    REQUIRE(ann.send(Ping{}));
    expect<Pong>(ann);
}

TEST_CASE("hall: the longest record the hall keeps fits its allowance", "[hall]") {
    // Each number as long as its shortest text can be (a sign, 17 digits, a three-digit
    // exponent), every optional field.
    RecordedAction shot;
    shot.kind = RecordedAction::Kind::shot;
    constexpr double longest = -1.2345678901234567e-300;
    shot.strike = {-longest, longest, longest, longest, -longest};
    REQUIRE(format_double(longest).size() == 24); // the longest there is (text_numbers.cpp)
    shot.call.call.ball = 15;
    shot.call.call.pocket = 6;
    shot.call.push_out = true;
    const std::size_t line =
        format_server(RecordLine{max_table_number, format_action(shot)}).size();
    CHECK(line <= 170);
    GameRecord header;
    header.names[0] = header.names[1] = std::string(max_player_name_bytes, 'W');
    std::size_t whole = 0;
    const std::string text = format_record(header);
    for (std::size_t start = 0; start < text.size(); start = text.find('\n', start) + 1)
        whole += format_server(RecordLine{max_table_number,
                                          text.substr(start, text.find('\n', start) - start)})
                     .size();
    const ServerOptions defaults;
    whole +=
        defaults.max_actions * line + format_server(RecordEnd{max_table_number, 5000, 0}).size();
    INFO("the longest record on the wire: " << whole << " bytes");
    CHECK(whole <= defaults.record_allowance);
}

namespace {

// A connection's socket and its peer's end, the peer read by the test.
struct SocketPair {
    SocketPair() {
        int fds[2];
        REQUIRE(::socketpair(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK, 0, fds) == 0);
        ours = std::make_unique<Connection>(UniqueFd(fds[0]));
        peer = UniqueFd(fds[1]);
    }
    // Reads what the peer holds; the bytes read.
    std::size_t drain() {
        std::size_t total = 0;
        char buffer[65536];
        for (ssize_t n; (n = ::recv(peer.get(), buffer, sizeof buffer, 0)) > 0;)
            total += static_cast<std::size_t>(n);
        return total;
    }
    std::unique_ptr<Connection> ours;
    UniqueFd peer;
};

} // namespace

TEST_CASE("hall connection: a bulk's allowance counts what the client failed to read, one bulk "
          "at a time",
          "[hall]") {
    constexpr std::size_t limit = 1000, allowance = 5000;
    SocketPair pair;
    Connection& c = *pair.ours;
    // A bulk over the limit is taken; what comes after it counts on its own.
    REQUIRE(c.queue_bulk(std::string(4000, 'r'), limit, allowance));
    CHECK(c.queued() == 4000);
    CHECK(c.owed() == 0);
    REQUIRE(c.queue(std::string(900, 'a'), limit));
    CHECK(c.owed() == 900);
    CHECK_FALSE(c.queue(std::string(200, 'a'), limit)); // 1100 owed: a slow reader
}

TEST_CASE("hall connection: a second bulk while the first waits counts in full", "[hall]") {
    constexpr std::size_t limit = 1000, allowance = 5000;
    SocketPair pair;
    Connection& c = *pair.ours;
    REQUIRE(c.queue_bulk(std::string(4000, 'r'), limit, allowance));
    CHECK_FALSE(c.queue_bulk(std::string(4000, 'r'), limit, allowance));
}

TEST_CASE("hall connection: the allowance shrinks as the bulk is written, then a new bulk is "
          "granted",
          "[hall]") {
    constexpr std::size_t limit = 1000, allowance = 500000;
    SocketPair pair;
    Connection& c = *pair.ours;
    const std::string record(400000, 'r'); // more than the socket takes at once
    REQUIRE(c.queue_bulk(record, limit, allowance));
    REQUIRE(c.flush());
    REQUIRE(c.wants_write());
    // What is written no longer counts as allowance: the rest still does, nothing is owed.
    CHECK(c.owed() == 0);
    CHECK(c.queued() < record.size());
    std::size_t read = 0;
    // The client reads at full speed: the whole record comes.
    while (c.wants_write()) {
        read += pair.drain();
        REQUIRE(c.flush());
    }
    read += pair.drain();
    CHECK(read == record.size());
    CHECK(c.owed() == 0);
    // Read: the next bulk is granted again.
    REQUIRE(c.queue_bulk(record, limit, allowance));
    CHECK(c.owed() == 0);
}

TEST_CASE("hall connection: a bulk over its allowance counts its excess", "[hall]") {
    SocketPair pair;
    Connection& c = *pair.ours;
    REQUIRE(c.queue_bulk(std::string(1500, 'r'), 1000, 600));
    CHECK(c.owed() == 900);
    CHECK_FALSE(c.queue_bulk(std::string(100, 'r'), 900, 600)); // counted: 1000 owed
}
