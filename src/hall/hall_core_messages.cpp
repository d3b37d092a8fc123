// The hall core's messages: each line read, parsed, budgeted and handed to its handler.

#include "hall/hall_core.hpp"

namespace termpool::hall {

void HallCore::on_message(Client& client, const ClientMessage& message, Clock::time_point now) {
    // The host's question: before hello too, since `termpool hall who` has no name to give
    // (the socket's folder is its user's alone: whoever reaches it may say hello anyway).
    // Budgeted like the other requests that make the hall work for one client.
    if (std::holds_alternative<Who>(message)) {
        if (!client.requests.take(options_.request_rate, options_.request_burst, now))
            return send_error(client, ErrorCode::rate, "too many requests: slow down", now);
        std::string text;
        for (std::string& line : who_lines(client.id, now))
            text += format_server(WhoLine{std::move(line)});
        return send_text(client, text + format_server(WhoEnd{}));
    }
    if (!client.welcomed && !std::holds_alternative<Hello>(message))
        return send_error(client, ErrorCode::hello_first, "say hello first", now);
    if (!std::holds_alternative<Ping>(message))
        client.last_heard = now; // a ping alone does not keep a place in a full hall
    // An action at a table waits for its save (settle) until the round ends, unless a
    // message could see or change that table first: every message but an action, an aim
    // or a chat line at the sender's own table settles the round's actions before it is
    // handled, so that it finds each table as if every action had been saved at once.
    const bool own_table_only =
        std::holds_alternative<Act>(message) || std::holds_alternative<NextRack>(message) ||
        std::holds_alternative<Aim>(message) || std::holds_alternative<Chat>(message) ||
        std::holds_alternative<Ping>(message);
    if (const Table* own = table_of(client);
        !batch_.empty() && (!own_table_only || (own && own->saving)))
        settle(now);
    if (const auto* m = std::get_if<Hello>(&message))
        return on_hello(client, *m, now);
    // The requests that send a record or change the lobby have a budget, so that one
    // client cannot make the hall busy for everyone.
    const bool costly =
        std::holds_alternative<Create>(message) || std::holds_alternative<Sit>(message) ||
        std::holds_alternative<Watch>(message) || std::holds_alternative<Leave>(message) ||
        std::holds_alternative<Sync>(message);
    if (costly && !client.requests.take(options_.request_rate, options_.request_burst, now))
        return send_error(client, ErrorCode::rate, "too many requests: slow down", now);
    if (const auto* m = std::get_if<Create>(&message))
        return on_create(client, *m, now);
    if (const auto* m = std::get_if<Sit>(&message))
        return on_sit(client, *m, now);
    if (const auto* m = std::get_if<Watch>(&message))
        return on_watch(client, *m, now);
    if (std::holds_alternative<Leave>(message)) {
        const int number = client.table;
        if (number == 0)
            return send_error(client, ErrorCode::no_table, "you are at no table", now);
        leave_table(client, now);
        return send(client, Left{number});
    }
    if (const auto* m = std::get_if<Act>(&message))
        return on_act(client, m->action, now);
    if (std::holds_alternative<NextRack>(message)) {
        RecordedAction rack;
        rack.kind = RecordedAction::Kind::rack;
        return on_act(client, rack, now);
    }
    if (const auto* m = std::get_if<Aim>(&message))
        return on_aim(client, *m, now);
    if (const auto* m = std::get_if<Chat>(&message))
        return on_chat(client, *m, now);
    if (const auto* m = std::get_if<SeatComputer>(&message))
        return on_computer(client, *m, now);
    if (const auto* m = std::get_if<Sync>(&message))
        return on_sync(client, *m, now);
    send(client, Pong{});
}

void HallCore::on_line(int id, std::string_view line, Clock::time_point now) {
    const auto found = clients_.find(id);
    if (found == clients_.end() || found->second.closing)
        return;
    Client& client = found->second;
    auto parsed = parse_client(line);
    if (const auto* error = std::get_if<ProtocolError>(&parsed)) {
        if (error->code == ErrorCode::version)
            return send_and_close(client, ErrorCode::version, error->text);
        return send_error(client, error->code, error->text, now);
    }
    on_message(client, std::get<ClientMessage>(parsed), now);
}

} // namespace termpool::hall
