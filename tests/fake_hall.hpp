#pragma once
// A hall core driven by direct calls with a fake clock, for the tests: clients are ids, what
// the core says to each is parsed and kept per client, and time moves only when a test moves
// it. No socket, no thread but the computer pool's, no sleep.

#include <catch2/catch.hpp>
#include <chrono>
#include <deque>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <variant>

#include "hall/hall_core.hpp"
#include "hall_helpers.hpp"

namespace termpool::test {

/// A HallCore, its clock, and what each client received.
class FakeHall {
public:
    using Clock = hall::HallCore::Clock;

    /// A hall with `options` (deal_seed 7 unless given; no state folder unless given), and its
    /// clock at an arbitrary start.
    explicit FakeHall(hall::ServerOptions options = {})
        : core_(seeded(std::move(options)), {}, [this] { return now; }) {}

    /// The time the core is told.
    Clock::time_point now = Clock::time_point{} + std::chrono::hours(1000);
    /// The system clock's time at `now` (for restore).
    std::chrono::system_clock::time_point wall_now = std::chrono::system_clock::now();

    hall::HallCore& core() { return core_; }

    /// Restores the state folder's tables.
    void restore() {
        core_.restore(now, wall_now);
        collect();
    }
    /// A new connection's id.
    int connect() {
        const int id = next_id_++;
        core_.on_connect(id, now);
        collect();
        return id;
    }
    /// A new connection that said hello as `name` (with `token`, or asking for one); its id.
    int hello(const std::string& name, const std::string& token = "") {
        const int id = connect();
        send(id, hall::Hello{hall::protocol_version, token, name});
        const auto welcome = find<hall::Welcome>(id);
        REQUIRE(welcome);
        tokens_[id] = welcome->token;
        return id;
    }
    /// `id` says `message` (one line).
    void send(int id, const hall::ClientMessage& message) {
        std::string line = hall::format_client(message);
        line.pop_back(); // its '\n'
        send_raw(id, line);
    }
    /// `id` sends the line `line` (without its '\n').
    void send_raw(int id, const std::string& line) {
        core_.on_line(id, line, now);
        collect();
    }
    /// `id`'s connection went.
    void disconnect(int id) {
        core_.on_disconnect(id, now);
        closed_.insert(id);
        collect();
    }
    /// The end of a round at `now`.
    void tick() {
        core_.tick(now);
        collect();
    }
    /// Time passes by `d`, then a round ends.
    void advance(Clock::duration d) {
        now += d;
        tick();
    }
    /// Waits (at most kWait) for the computer's answer and takes it, then ends the round.
    bool computer() {
        const bool answered = core_.await_computer(kWait, now);
        collect();
        tick();
        return answered;
    }
    /// The token `id` was welcomed with.
    const std::string& token(int id) { return tokens_[id]; }
    /// True once the core asked to end `id`'s connection (or it disconnected).
    bool closed(int id) const { return closed_.count(id) != 0; }
    /// Everything `id` received not taken yet, and forgets it.
    std::deque<hall::ServerMessage> take(int id) { return std::exchange(received_[id], {}); }
    /// The first T `id` received not taken yet, and what came before it is dropped; nothing
    /// when none came (all that came is dropped then).
    template <class T> std::optional<T> find(int id) {
        auto& queue = received_[id];
        while (!queue.empty()) {
            hall::ServerMessage m = std::move(queue.front());
            queue.pop_front();
            if (auto* found = std::get_if<T>(&m))
                return std::move(*found);
        }
        return std::nullopt;
    }
    /// The code of the first error `id` received not taken yet.
    std::optional<hall::ErrorCode> error(int id) {
        const auto e = find<hall::Error>(id);
        return e ? std::optional(e->code) : std::nullopt;
    }

    /// `id` creates a table; its number (the test stops on a refusal).
    int create(int id, GameType game = GameType::eight_ball) {
        send(id, hall::Create{game, TableSize::seven_foot, 1});
        for (const hall::ServerMessage& m : take(id)) {
            if (const auto* e = std::get_if<hall::Error>(&m))
                FAIL("create refused: " << e->text);
            if (const auto* c = std::get_if<hall::Created>(&m))
                return c->table;
        }
        FAIL("no answer to create");
        return 0;
    }
    /// `id` sits at `seat` of `table` and gets its record.
    void sit(int id, int table, int seat) {
        send(id, hall::Sit{table, seat});
        const auto end = find<hall::RecordEnd>(id);
        REQUIRE(end);
        CHECK(end->table == table);
    }
    /// Two people and the table they sit at: the setting most tests start from.
    struct TwoSeated {
        int ann;
        int bob;
        int table;
    };
    /// Ann and Bob say hello, Ann creates an 8-ball table, Ann takes seat 1 and Bob seat 2.
    TwoSeated ann_and_bob_seated() {
        const int ann = hello("Ann");
        const int bob = hello("Bob");
        const int table = create(ann);
        sit(ann, table, 1);
        sit(bob, table, 2);
        return {ann, bob, table};
    }
    /// The player to act at `table`, seated by `seat_1` or `seat_2`, plays the easy computer's
    /// move; it is taken at the end of the round.
    void play_one(int seat_1, int seat_2, int table) {
        const Match* match = core_.match(table);
        REQUIRE(match);
        const std::size_t seq = match->record().actions.size() + 1;
        const int actor = match->to_act() == 1 ? seat_1 : seat_2;
        send(actor, hall::Act{chosen_move(*match)});
        tick();
        REQUIRE(core_.match(table)->record().actions.size() == seq);
    }

private:
    static hall::ServerOptions seeded(hall::ServerOptions options) {
        if (!options.deal_seed)
            options.deal_seed = 7;
        return options;
    }
    void collect() {
        for (hall::Outgoing& out : core_.take_outbox()) {
            for (std::size_t start = 0; start < out.text.size();) {
                const std::size_t end = out.text.find('\n', start);
                REQUIRE(end != std::string::npos);
                auto parsed =
                    hall::parse_server(std::string_view(out.text).substr(start, end - start));
                REQUIRE(std::holds_alternative<hall::ServerMessage>(parsed));
                received_[out.client].push_back(std::get<hall::ServerMessage>(std::move(parsed)));
                start = end + 1;
            }
            if (out.close)
                closed_.insert(out.client);
        }
    }

    hall::HallCore core_;
    int next_id_ = 1;
    std::map<int, std::deque<hall::ServerMessage>> received_;
    std::map<int, std::string> tokens_;
    std::set<int> closed_;
};

} // namespace termpool::test
