// The hall's line protocol: every message formats to one line that reads back to the same
// line, and malformed, oversized and other-version lines are refused with the right code.
#include <catch2/catch.hpp>
#include <string>
#include <variant>
#include <vector>

#include "hall/protocol.hpp"

using namespace termpool;
using namespace termpool::hall;

namespace {

const std::string kToken = "0123456789abcdef0123456789abcdef";

RecordedAction action_of(const std::string& line) {
    auto parsed = parse_action(line);
    REQUIRE(std::holds_alternative<RecordedAction>(parsed));
    return std::get<RecordedAction>(parsed);
}

std::string body(const std::string& line) {
    REQUIRE(!line.empty());
    REQUIRE(line.back() == '\n');
    return line.substr(0, line.size() - 1);
}

// Formats, parses and formats again: the same line both times.
void client_round_trip(const ClientMessage& message) {
    const std::string line = format_client(message);
    INFO(line);
    CHECK(line.size() <= max_line_bytes);
    const auto parsed = parse_client(body(line));
    if (const auto* e = std::get_if<ProtocolError>(&parsed))
        FAIL(e->text);
    const auto& again = std::get<ClientMessage>(parsed);
    CHECK(again.index() == message.index());
    CHECK(format_client(again) == line);
}

void server_round_trip(const ServerMessage& message) {
    const std::string line = format_server(message);
    INFO(line);
    CHECK(line.size() <= max_line_bytes);
    const auto parsed = parse_server(body(line));
    if (const auto* e = std::get_if<ProtocolError>(&parsed))
        FAIL(e->text);
    const auto& again = std::get<ServerMessage>(parsed);
    CHECK(again.index() == message.index());
    CHECK(format_server(again) == line);
}

ErrorCode client_refusal(const std::string& line) {
    INFO(line);
    const auto parsed = parse_client(line);
    REQUIRE(std::holds_alternative<ProtocolError>(parsed));
    return std::get<ProtocolError>(parsed).code;
}

ErrorCode server_refusal(const std::string& line) {
    INFO(line);
    const auto parsed = parse_server(line);
    REQUIRE(std::holds_alternative<ProtocolError>(parsed));
    return std::get<ProtocolError>(parsed).code;
}

} // namespace

TEST_CASE("hall protocol: every client message reads back", "[hall]") {
    client_round_trip(Hello{protocol_version, "", "Ann"});
    client_round_trip(Hello{protocol_version, kToken, "Ann Marie 100%"});
    client_round_trip(Create{GameType::nine_ball, TableSize::seven_foot, 5});
    client_round_trip(Create{GameType::ten_ball, TableSize::nine_foot, 3});
    client_round_trip(Create{GameType::eight_ball_bar, TableSize::eight_foot, 1});
    client_round_trip(Create{GameType::eight_ball, TableSize::snooker, 3});
    client_round_trip(Create{GameType::snooker, TableSize::snooker, 3});
    client_round_trip(Create{GameType::eight_ball, TableSize::nine_foot, 1, Assist::guided});
    client_round_trip(Create{GameType::nine_ball, TableSize::nine_foot, 2, Assist::pro});
    client_round_trip(Sit{12, 2});
    client_round_trip(Watch{9999});
    client_round_trip(Leave{});
    client_round_trip(Act{action_of("place 0.6 0.5")});
    client_round_trip(Act{action_of("shot 12 0 0 0 call 1 3")});
    client_round_trip(Act{action_of("shot 3.25 181.5 -0.25 0.5 safety")});
    client_round_trip(Act{action_of("shot 1.5 10 0.3 0 elevation 30 call 1 3")});
    client_round_trip(Act{action_of("choose play-on")});
    client_round_trip(NextRack{});
    client_round_trip(Aim{Strike{7.5, 123.456, 0.1, -0.2}});
    client_round_trip(Aim{Strike{1.25, -30, -0.35, 0.1, 42.5}});
    client_round_trip(Chat{"good shot, 100% — ünïcödé"});
    client_round_trip(SeatComputer{2, Level::pro});
    client_round_trip(SeatComputer{1, std::nullopt});
    client_round_trip(Sync{});
    client_round_trip(Sync{17, 0x0123456789abcdefull});
    client_round_trip(Sync{0, 0});
    client_round_trip(Ping{});
}

TEST_CASE("hall protocol: a table's assist is created and listed by name", "[hall]") {
    CHECK(format_client(Create{GameType::eight_ball, TableSize::nine_foot, 3, Assist::guided}) ==
          "create 8ball 9ft 3 guided\n");
    const auto create = parse_client("create 9ball 7ft 1 pro");
    REQUIRE(std::holds_alternative<ClientMessage>(create));
    CHECK(std::get<Create>(std::get<ClientMessage>(create)).assist == Assist::pro);
    const auto table = parse_server("table 2 8ball 9ft 1 guided waiting player Ann empty - 0");
    REQUIRE(std::holds_alternative<ServerMessage>(table));
    CHECK(std::get<TableView>(std::get<ServerMessage>(table)).assist == Assist::guided);
    CHECK(std::get<TableView>(std::get<ServerMessage>(table)).seats[0].name == "Ann");
}

TEST_CASE("hall protocol: every server message reads back", "[hall]") {
    server_round_trip(Welcome{protocol_version, kToken});
    server_round_trip(Error{ErrorCode::refused, "it is the other player's turn"});
    server_round_trip(Error{ErrorCode::too_long, ""});
    server_round_trip(LobbyBegin{});
    TableView table;
    table.number = 3;
    table.game = GameType::nine_ball;
    table.size = TableSize::eight_foot;
    table.race_to = 7;
    table.state = TableState::playing;
    table.seats[0] = {SeatKind::away, "Bob the Builder"};
    table.seats[1] = {SeatKind::computer, "Computer (hard)"};
    table.spectators = 4;
    server_round_trip(table);
    table.seats[0] = {SeatKind::empty, ""};
    table.state = TableState::waiting;
    server_round_trip(table);
    table.size = TableSize::snooker;
    server_round_trip(table);
    table.assist = Assist::guided;
    server_round_trip(table);
    table.assist = Assist::pro;
    server_round_trip(table);
    server_round_trip(PlayerView{"Ann", 0, 0});
    server_round_trip(PlayerView{"Ann", 3, 2});
    server_round_trip(LobbyEnd{});
    server_round_trip(Created{1});
    server_round_trip(Joined{1, 0});
    server_round_trip(Left{1});
    server_round_trip(Yours{4, 2});
    server_round_trip(RecordLine{1, "names Ann Bob"});
    server_round_trip(RecordLine{1, ""});
    server_round_trip(RecordEnd{1, 42, 0xfedcba9876543210ULL});
    server_round_trip(SeatChange{2, 1, {SeatKind::player, "Ann"}});
    server_round_trip(SeatChange{2, 2, {SeatKind::empty, ""}});
    server_round_trip(ActionDone{2, 7, 1, action_of("rack 2 1234")});
    server_round_trip(ActionDone{2, 8, 0, action_of("shot 12 0 0 0 call 1 3 push-out")});
    server_round_trip(AimShown{2, 1, Strike{1, 2, 0.5, -0.5}});
    server_round_trip(AimShown{2, 2, Strike{1, 2, 0.5, -0.5, max_cue_elevation_deg}});
    server_round_trip(ChatShown{2, "Ann", "hi there"});
    server_round_trip(Pong{});
}

TEST_CASE("hall protocol: text fields stay one field", "[hall]") {
    CHECK(encode_field("a b%c") == "a%20b%25c");
    CHECK(encode_field("\n\x7f") == "%0A%7F");
    CHECK(decode_field("a%20b%25c") == std::optional<std::string>("a b%c"));
    CHECK_FALSE(decode_field("a%2"));
    CHECK_FALSE(decode_field("a%zz"));
    CHECK_FALSE(decode_field("a%41")); // 'A' needs no escape: one text, one encoding
    CHECK_FALSE(decode_field("a%0a")); // lower-case hex is not ours
    CHECK(valid_chat_text("hello"));
    CHECK(valid_chat_text(std::string(200, 'x')));
    CHECK_FALSE(valid_chat_text(std::string(201, 'x')));
    CHECK(valid_chat_text(std::string(200 * 2 / 2, 'y')));
    CHECK_FALSE(valid_chat_text(""));
    CHECK_FALSE(valid_chat_text("tab\there"));
    CHECK_FALSE(valid_chat_text("\xc2\x85"));     // C1 NEL
    CHECK_FALSE(valid_chat_text("\xc0\xaf"));     // overlong
    CHECK_FALSE(valid_chat_text("\xed\xa0\x80")); // surrogate
}

TEST_CASE("hall protocol: malformed client lines are refused", "[hall]") {
    const std::vector<std::string> bad = {
        "",
        " ",
        "ping ",
        "ping extra",
        "PING",
        "hello 3 - ",
        "hello 3 -",
        "hello 3 abc Ann",
        "hello 3 0123456789ABCDEF0123456789ABCDEF Ann",
        "hello 3 - %20Ann",
        "hello 3 - Ann%",
        "hello one - Ann",
        "create 11ball 9ft 1 standard",
        "create 8ball 10ft 1 standard",
        "create 8ball 9ft 0 standard",
        "create 8ball 9ft 100 standard",
        "create 8ball 9ft +5 standard",
        "create 8ball 9ft 1",
        "create 8ball 9ft 1 helpful",
        "create 8ball 9ft 1 Guided",
        "create 8ball 9ft 1 pro extra",
        "sit 0 1",
        "sit 1 3",
        "sit 1  1",
        "sit 10000 1",
        "sit 1 1.0",
        "watch",
        "watch -1",
        "act",
        "act rack 1 2",
        "act shot nan 0 0 0",
        "act shot 12 0 0.9 0",
        "act place x y",
        "act choose dance",
        "aim 0 21 0 0 0",
        "aim 0 1 0.6 0 0",
        "aim inf 1 0 0 0",
        "aim 0 1 0 0",
        "aim 0 1 0 0 -1",
        "aim 0 1 0 0 81",
        "aim 0 1 0 0 nan",
        "act shot 1 0 0 0 elevation 90",
        "chat",
        "chat a b",
        "chat %09",
        "chat " + std::string(201, 'x'),
        "computer 3 hard",
        "computer 1 godlike",
        "next-rack now",
        "sync\r",
        "sync ",
        "sync 17",
        "sync 17 ",
        "sync -1 0123456789abcdef",
        "sync 17 0123456789ABCDEF",
        "sync 17 0123456789abcdef extra",
        "sync x 0123456789abcdef",
        std::string("ping\0", 5),
        "\xff\xfe garbage",
    };
    for (const std::string& line : bad)
        CHECK(client_refusal(line) == ErrorCode::syntax);
}

TEST_CASE("hall protocol: oversized lines and other versions", "[hall]") {
    // The longest line that fits: 4095 bytes and the newline.
    const std::string longest = "chat " + std::string(max_line_bytes - 1 - 5, 'x');
    CHECK(client_refusal(longest) == ErrorCode::syntax); // over 200 characters, but not too long
    CHECK(client_refusal(longest + "x") == ErrorCode::too_long);
    CHECK(server_refusal("record 1 " + std::string(max_line_bytes, 'x')) == ErrorCode::too_long);
    const std::string fits = "record 1 " + std::string(max_line_bytes - 1 - 9, 'x');
    CHECK(std::holds_alternative<ServerMessage>(parse_server(fits)));

    // Version 1 had no elevation in `aim`, version 2 no assist in `create` and `table`: their
    // clients are turned away.
    CHECK(client_refusal("hello 1 - Ann") == ErrorCode::version);
    CHECK(client_refusal("hello 2 - Ann") == ErrorCode::version);
    CHECK(client_refusal("hello 4 - Ann") == ErrorCode::version);
    CHECK(client_refusal("hello 0 - Ann") == ErrorCode::version);
    CHECK(client_refusal("hello 4 some future format") == ErrorCode::version);
    CHECK(server_refusal("welcome 2 " + kToken) == ErrorCode::version);
    CHECK(server_refusal("welcome 4 " + kToken) == ErrorCode::version);
}

TEST_CASE("hall protocol: malformed server lines are refused", "[hall]") {
    const std::vector<std::string> bad = {
        "welcome 3 xyz",
        "error nonsense oops",
        "error refused tab\there",
        "table 1 8ball 9ft 1 standard waiting empty Ann empty - 0",
        "table 1 8ball 9ft 1 standard dancing empty - empty - 0",
        "table 1 8ball 9ft 1 standard waiting player %2 empty - 0",
        "table 1 8ball 9ft 1 standard waiting empty - empty - -1",
        "table 1 8ball 9ft 1 waiting empty - empty - 0",
        "table 1 8ball 9ft 1 easy waiting empty - empty - 0",
        "player Ann 0 1",
        "record-end 1 3 123",
        "record-end 1 3 FEDCBA9876543210",
        "action 1 0 fedcba9876543210 choose play-on",
        "action 1 1 fedcba9876543210 fly away",
        "seat 1 0 empty -",
        "chat 1 Ann",
        "aim 1 1 0 1 0 0",
        "aim 1 1 0 1 0 0 95",
        "record 1",
    };
    for (const std::string& line : bad)
        CHECK(server_refusal(line) == ErrorCode::syntax);
}

TEST_CASE("hall protocol: every number has one text", "[hall]") {
    // What the formatters write reads; any other text of the same value is refused, so that
    // one message has one line (a log, a hash or a test may compare lines).
    const std::string hash = "fedcba9876543210";
    const std::vector<std::pair<std::string, std::vector<std::string>>> client = {
        {"sit 1 2", {"sit 01 2", "sit 1 02", "sit +1 2", "sit 1 +2", "sit 001 2"}},
        {"watch 10", {"watch 010", "watch +10", "watch 1e1"}},
        {"create 8ball 9ft 3 standard", {"create 8ball 9ft 03 standard"}},
        {"computer 2 hard", {"computer 02 hard"}},
        {"sync 17 " + hash, {"sync 017 " + hash, "sync +17 " + hash}},
        {"sync 0 " + hash, {"sync 00 " + hash, "sync -0 " + hash}},
        {"hello 3 - Ann", {"hello 03 - Ann", "hello +3 - Ann"}},
        {"aim 0 1.5 0 0 0",
         {"aim -0 1.5 0 0 0", "aim 0 1.50 0 0 0", "aim 0 +1.5 0 0 0", "aim 0 15e-1 0 0 0",
          "aim 0 01.5 0 0 0", "aim 0.0 1.5 0 0 0"}},
        {"act shot 1.5 0 0 0 call 1 3",
         {"act shot 1.50 0 0 0 call 1 3", "act shot 1.5 0 0 0 call 01 3",
          "act shot 1.5 -0 0 0 call 1 3", "act shot 1.5 0 0 0  call 1 3",
          "act shot 1.5 0 0 0 call 1 3 ", "act shot 1.5 0 0 0 call 1 +3"}},
        {"act place 0.5 0.25", {"act place .5 0.25", "act place 0.5 2.5e-1"}},
        // A game has other names a player may type; the protocol takes its own.
        {"create 10ball 9ft 1 standard", {"create 10-ball 9ft 1 standard"}},
    };
    for (const auto& [good, others] : client) {
        INFO(good);
        const auto parsed = parse_client(good);
        REQUIRE(std::holds_alternative<ClientMessage>(parsed));
        CHECK(format_client(std::get<ClientMessage>(parsed)) == good + "\n");
        for (const std::string& other : others)
            CHECK(client_refusal(other) == ErrorCode::syntax);
    }
    const std::vector<std::pair<std::string, std::vector<std::string>>> server = {
        {"joined 4 1", {"joined 04 1", "joined 4 01"}},
        {"record-end 2 15 " + hash, {"record-end 2 015 " + hash}},
        {"action 2 3 " + hash + " choose play-on", {"action 2 03 " + hash + " choose play-on"}},
        {"action 2 3 " + hash + " rack 1 17", {"action 2 3 " + hash + " rack 1 017"}},
        {"welcome 3 " + kToken, {"welcome 03 " + kToken}},
        {"table 1 10ball 9ft 1 standard waiting empty - empty - 0",
         {"table 1 10ball 9ft 1 standard waiting empty - empty - 00",
          "table 1 ten-ball 9ft 1 standard waiting empty - empty - 0"}},
    };
    for (const auto& [good, others] : server) {
        INFO(good);
        const auto parsed = parse_server(good);
        REQUIRE(std::holds_alternative<ServerMessage>(parsed));
        CHECK(format_server(std::get<ServerMessage>(parsed)) == good + "\n");
        for (const std::string& other : others)
            CHECK(server_refusal(other) == ErrorCode::syntax);
    }
    // The refusal says what was wrong.
    const auto sit = parse_client("sit 01 1");
    REQUIRE(std::holds_alternative<ProtocolError>(sit));
    CHECK(std::get<ProtocolError>(sit).text == "a table must be a whole number from 1 to 9999");
}

TEST_CASE("hall protocol: a name in hello holds nothing invisible and no direction control",
          "[hall]") {
    // Each as the client would encode it: the bytes of the character, percent-encoded where
    // needed.
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"Ann\u200B", "U+200B (an invisible character)"},
        {"\u200BAnn", "U+200B (an invisible character)"},
        {"An\u00ADn", "U+00AD (an invisible character)"},
        {"Ann\u200D", "U+200D (an invisible character)"},
        {"Ann\u2060", "U+2060 (an invisible character)"},
        {"Ann\uFEFF", "U+FEFF (an invisible character)"},
        {"Ann\u3164", "U+3164 (an invisible character)"},
        {"Ann\U000E0041", "U+E0041 (an invisible character)"},
        {"\u202EnnA", "U+202E (it changes the direction of the text)"},
        {"Ann\u202A", "U+202A (it changes the direction of the text)"},
        {"Ann\u2066", "U+2066 (it changes the direction of the text)"},
        {"Ann\u2069", "U+2069 (it changes the direction of the text)"},
        {"Ann\u200E", "U+200E (it changes the direction of the text)"},
        {"Ann\u200F", "U+200F (it changes the direction of the text)"},
        {"Ann\u061C", "U+061C (it changes the direction of the text)"},
        {"Ann\u2028", "U+2028 (a line or paragraph separator)"},
        {"Ann\u0600", "U+0600 (an invisible character)"},
        {"Ann\u0085", "no control characters"},
        {"Ann\x1b", "no control characters"},
    };
    for (const auto& [name, why] : bad) {
        const std::string line = body(format_client(Hello{protocol_version, "", name}));
        INFO(line);
        const auto parsed = parse_client(line);
        REQUIRE(std::holds_alternative<ProtocolError>(parsed));
        CHECK(std::get<ProtocolError>(parsed).code == ErrorCode::syntax);
        CHECK(std::get<ProtocolError>(parsed).text.find(why) != std::string::npos);
    }
    // Letters of any script, marks that combine with them and emoji without a joiner stay.
    for (const std::string name : {"Ann", "Ann Lee", "Zoë", "Zoe\u0308", "Åsa", "李小龍", "محمد",
                                   "שרה", "Ａｎｎ", "🎱 Ann"}) {
        INFO(name);
        client_round_trip(Hello{protocol_version, "", name});
    }
}

TEST_CASE("hall protocol: a name in hello is at most 20 columns wide, as the prompt cuts it",
          "[hall]") {
    for (const std::string& name :
         {std::string(20, 'W'), std::string("李小龍李小龍李小龍李"), // 10: 20 columns
          std::string(19, 'a') + "\u0308"}) {
        INFO(name);
        client_round_trip(Hello{protocol_version, "", name});
    }
    for (const std::string& name :
         {std::string(21, 'W'), std::string("李小龍李小龍李小龍李小"), // 11: 22
          std::string(20, 'a') + "李"}) {
        const std::string line = body(format_client(Hello{protocol_version, "", name}));
        INFO(line);
        const auto parsed = parse_client(line);
        REQUIRE(std::holds_alternative<ProtocolError>(parsed));
        CHECK(std::get<ProtocolError>(parsed).code == ErrorCode::syntax);
        CHECK(std::get<ProtocolError>(parsed).text == "a name is at most 20 columns wide");
    }
}

TEST_CASE("hall protocol: chat holds nothing invisible and nothing that turns the line around",
          "[hall]") {
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"rtl \u202Egnp.exe", "chat may not hold U+202E (it changes the direction of the text)"},
        {"a\u2066b", "chat may not hold U+2066 (it changes the direction of the text)"},
        {"zero\u200Bwidth", "chat may not hold U+200B (an invisible character)"},
        {"one\u2028two", "chat may not hold U+2028 (a line or paragraph separator)"},
        {"\uFEFFhi", "chat may not hold U+FEFF (an invisible character)"},
        {"hi\U000E0041", "chat may not hold U+E0041 (an invisible character)"},
        {" ", "chat of nothing that shows says nothing"},
        {"    ", "chat of nothing that shows says nothing"},
        {"\u00A0\u3000\u2003", "chat of nothing that shows says nothing"},
        {"\u0301\u0301\u0301", "chat of nothing that shows says nothing"},
        {"\u200D\u200D\uFE0F", "chat of nothing that shows says nothing"},
    };
    for (const auto& [text, why] : bad) {
        const std::string line = body(format_client(Chat{text}));
        INFO(line);
        const auto parsed = parse_client(line);
        REQUIRE(std::holds_alternative<ProtocolError>(parsed));
        CHECK(std::get<ProtocolError>(parsed).code == ErrorCode::syntax);
        CHECK(std::get<ProtocolError>(parsed).text == why);
    }
    // Any script, combining marks and emoji stay, with the joiners and variation selectors
    // they are written with (a family, a red heart, a Persian word with a zero-width non-joiner);
    // so does chat the server sends (it sent only what it took, and a table kept from an older
    // hall may hold a line it took then).
    for (const std::string text : {"nice shot", "Zoe\u0308!", "שלום", "李小龍 🎱", "gg ✓",
                                   "\U0001F468\u200D\U0001F469\u200D\U0001F467", "\u2764\uFE0F",
                                   "\u0645\u06CC\u200C\u062E\u0648\u0627\u0647\u0645"}) {
        INFO(text);
        client_round_trip(Chat{text});
    }
    const auto shown = parse_server(body(format_server(ChatShown{1, "Ann", "zero\u200Bwidth"})));
    REQUIRE(std::holds_alternative<ServerMessage>(shown));
    CHECK(std::holds_alternative<ChatShown>(std::get<ServerMessage>(shown)));
}
