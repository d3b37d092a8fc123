// The hall server's messages: each line read, parsed, budgeted and handed to its handler.

#include "hall/server_state.hpp"

namespace termpool::hall {

void Server::State::on_message(Client& client, const ClientMessage& message) {
    if (!client.welcomed && !std::holds_alternative<Hello>(message))
        return send_error(client, ErrorCode::hello_first, "say hello first");
    // An action at a table waits for its save (settle) until the round ends, unless a
    // message could see or change that table first: every message but an action, an aim
    // or a chat line at the sender's own table settles the round's actions before it is
    // handled, so that it finds each table as if every action had been saved at once.
    const bool own_table_only =
        std::holds_alternative<Act>(message) || std::holds_alternative<NextRack>(message) ||
        std::holds_alternative<Aim>(message) || std::holds_alternative<Chat>(message) ||
        std::holds_alternative<Ping>(message);
    if (const Table* own = table_of(client);
        !batch.empty() && (!own_table_only || (own && own->saving)))
        settle();
    if (const auto* m = std::get_if<Hello>(&message))
        return on_hello(client, *m);
    // The requests that send a record or change the lobby have a budget, so that one
    // client cannot make the hall busy for everyone.
    const bool costly =
        std::holds_alternative<Create>(message) || std::holds_alternative<Sit>(message) ||
        std::holds_alternative<Watch>(message) || std::holds_alternative<Leave>(message) ||
        std::holds_alternative<Sync>(message);
    if (costly && !client.requests.take(options.request_rate, options.request_burst, Clock::now()))
        return send_error(client, ErrorCode::rate, "too many requests: slow down");
    if (const auto* m = std::get_if<Create>(&message))
        return on_create(client, *m);
    if (const auto* m = std::get_if<Sit>(&message))
        return on_sit(client, *m);
    if (const auto* m = std::get_if<Watch>(&message))
        return on_watch(client, *m);
    if (std::holds_alternative<Leave>(message)) {
        const int number = client.table;
        if (number == 0)
            return send_error(client, ErrorCode::no_table, "you are at no table");
        leave_table(client);
        return send(client, Left{number});
    }
    if (const auto* m = std::get_if<Act>(&message))
        return on_act(client, m->action);
    if (std::holds_alternative<NextRack>(message)) {
        RecordedAction rack;
        rack.kind = RecordedAction::Kind::rack;
        return on_act(client, rack);
    }
    if (const auto* m = std::get_if<Aim>(&message))
        return on_aim(client, *m);
    if (const auto* m = std::get_if<Chat>(&message))
        return on_chat(client, *m);
    if (const auto* m = std::get_if<SeatComputer>(&message))
        return on_computer(client, *m);
    if (const auto* m = std::get_if<Sync>(&message))
        return on_sync(client, *m);
    send(client, Pong{});
}

void Server::State::on_line(Client& client, std::string_view line) {
    auto parsed = parse_client(line);
    if (const auto* error = std::get_if<ProtocolError>(&parsed)) {
        if (error->code == ErrorCode::version)
            return send_and_close(client, ErrorCode::version, error->text);
        return send_error(client, error->code, error->text);
    }
    on_message(client, std::get<ClientMessage>(parsed));
}

} // namespace termpool::hall
