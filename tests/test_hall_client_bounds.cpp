// What a hall client takes from a server is bounded: a record's text and lines, the tables
// whose record comes at once, a lobby's rows. A server that sends more is broken: the client
// ends the connection and says why, never holds it all, never crashes.
#include <atomic>
#include <catch2/catch.hpp>
#include <cstring>
#include <string>
#include <sys/socket.h>
#include <sys/un.h>
#include <thread>

#include "hall/client.hpp"
#include "hall/server_bounds.hpp"
#include "hall_helpers.hpp"
#include "temp_dir.hpp"

using namespace termpool;
using namespace termpool::hall;
using namespace std::chrono_literals;

TEST_CASE("server bounds: a record's bytes and lines, records at once, lobby rows",
          "[hall][client-bounds]") {
    ServerBoundLimits limits;
    limits.record_bytes = 100;
    limits.record_lines = 5;
    limits.records_at_once = 2;
    limits.lobby_tables = 3;
    limits.lobby_players = 2;

    SECTION("a record's lines") {
        ServerBounds bounds(limits);
        for (int i = 0; i < 5; ++i)
            REQUIRE(bounds.check(RecordLine{1, "x"}) == "");
        CHECK(bounds.check(RecordLine{1, "x"}) == "a record of more than 5 lines");
    }
    SECTION("a record's bytes, and an ended record no longer counts") {
        ServerBounds bounds(limits);
        REQUIRE(bounds.check(RecordLine{1, std::string(90, 'x')}) == "");
        REQUIRE(bounds.check(RecordEnd{1, 0, 0}) == "");
        REQUIRE(bounds.check(RecordLine{1, std::string(90, 'x')}) == "");
        CHECK(bounds.check(RecordLine{2, std::string(10, 'x')}) ==
              "records of more than 100 bytes");
    }
    SECTION("records of many tables at once") {
        ServerBounds bounds(limits);
        REQUIRE(bounds.check(RecordLine{1, "x"}) == "");
        REQUIRE(bounds.check(RecordLine{2, "x"}) == "");
        CHECK(bounds.check(RecordLine{3, "x"}) == "records of more than 2 tables at once");
    }
    SECTION("a lobby's rows, counted anew with each snapshot") {
        ServerBounds bounds(limits);
        for (int snapshot = 0; snapshot < 3; ++snapshot) {
            REQUIRE(bounds.check(LobbyBegin{}) == "");
            for (int i = 0; i < 3; ++i)
                REQUIRE(bounds.check(TableView{}) == "");
            for (int i = 0; i < 2; ++i)
                REQUIRE(bounds.check(PlayerView{"Ann", 0, 0}) == "");
            REQUIRE(bounds.check(LobbyEnd{}) == "");
        }
        CHECK(bounds.check(TableView{}) == "");
        CHECK(bounds.check(PlayerView{"Ann", 0, 0}) == "");
        CHECK(bounds.check(PlayerView{"Ann", 0, 0}) == "");
        CHECK(bounds.check(PlayerView{"Ann", 0, 0}) == "a lobby of more than 2 players");
        CHECK(bounds.check(TableView{}) == "");
        CHECK(bounds.check(TableView{}) == "");
        CHECK(bounds.check(TableView{}) == "a lobby of more than 3 tables");
    }
}

namespace {

// Sends `line` `times` times on `fd` from a thread of its own, until the peer goes.
class Flood {
public:
    Flood(int fd, std::string text, std::size_t times)
        : thread_([fd, text = std::move(text), times, this] {
              for (std::size_t i = 0; i < times; ++i)
                  for (std::string_view rest = text; !rest.empty();) {
                      const ssize_t n = ::send(fd, rest.data(), rest.size(), MSG_NOSIGNAL);
                      if (n <= 0)
                          return;
                      sent_ += static_cast<std::size_t>(n);
                      rest.remove_prefix(static_cast<std::size_t>(n));
                  }
          }) {}
    ~Flood() { thread_.join(); }
    Flood(const Flood&) = delete;
    Flood& operator=(const Flood&) = delete;
    std::size_t sent() const { return sent_; }

private:
    std::atomic<std::size_t> sent_{0};
    std::thread thread_;
};

// Receives until the connection ends (at most kWait); the messages received.
std::size_t receive_until_closed(HallClient& client) {
    std::size_t messages = 0;
    for (const auto end = std::chrono::steady_clock::now() + test::kWait;
         !client.closed() && std::chrono::steady_clock::now() < end;)
        messages += client.receive(100ms).has_value();
    return messages;
}

} // namespace

TEST_CASE("hall client: a server that sends a record without end is broken: disconnected, and "
          "said so",
          "[hall][client-bounds]") {
    test::TempDir dir("termpool-hall");
    HallClient client;
    UniqueFd server = test::fake_server_for(client, dir.path() + "/hall.sock");
    const std::string line = format_server(RecordLine{1, std::string(1000, 'x')});
    {
        Flood flood(server.get(), line, 20000); // 20 MB, more than the 8 MiB taken
        receive_until_closed(client);
        REQUIRE(client.closed());
        server.reset(); // the flood ends
    }
    CHECK(client.broken() == "the hall is broken: it sent records of more than 8388608 bytes");
    CHECK(client.match(1) == nullptr);
}

TEST_CASE("hall client: a server that sends a lobby without end is broken",
          "[hall][client-bounds]") {
    test::TempDir dir("termpool-hall");
    HallClient client;
    UniqueFd server = test::fake_server_for(client, dir.path() + "/hall.sock");
    TableView row;
    row.number = 12;
    { Flood begin(server.get(), format_server(LobbyBegin{}), 1); }
    {
        Flood flood(server.get(), format_server(row), 200000);
        receive_until_closed(client);
        REQUIRE(client.closed());
        server.reset();
    }
    CHECK(client.broken() == "the hall is broken: it sent a lobby of more than 9999 tables");
}

TEST_CASE("hall client: a whole record within the bounds is taken; a new connection counts "
          "anew",
          "[hall][client-bounds]") {
    test::TempDir dir("termpool-hall");
    HallClient client;
    ServerBoundLimits limits;
    limits.record_lines = 3;
    client.set_bounds(limits);
    UniqueFd server = test::fake_server_for(client, dir.path() + "/hall.sock");
    { Flood lines(server.get(), format_server(RecordLine{1, "x"}), 3); }
    for (int i = 0; i < 3; ++i)
        CHECK(client.receive(test::kWait));
    CHECK(client.broken() == "");
    { Flood line(server.get(), format_server(RecordLine{1, "x"}), 1); }
    CHECK_FALSE(client.receive(test::kWait));
    CHECK(client.closed());
    CHECK(client.broken() == "the hall is broken: it sent a record of more than 3 lines");
    server.reset();
    server = test::fake_server_for(client, dir.path() + "/hall2.sock");
    CHECK(client.broken() == "");
    { Flood lines(server.get(), format_server(RecordLine{1, "x"}), 3); }
    for (int i = 0; i < 3; ++i)
        CHECK(client.receive(test::kWait));
    CHECK_FALSE(client.closed());
}
