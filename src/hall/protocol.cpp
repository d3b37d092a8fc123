#include "hall/protocol.hpp"

#include "support/text_lines.hpp"
#include "support/text_numbers.hpp"
#include <charconv>
#include <cmath>
#include <termpool/match.hpp>
#include <termpool/name_characters.hpp>
#include <termpool/text_width.hpp>
#include <vector>

namespace termpool::hall {

namespace {

bool needs_escape(unsigned char byte) {
    return byte <= 0x20 || byte == 0x7f || byte == '%';
}

// A control character in raw rest-of-line text (C0 or DEL; C1 are UTF-8 pairs, harmless to
// the line structure).
bool has_control(std::string_view text) {
    for (const char c : text)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            return true;
    return false;
}

std::string number(double v) {
    return format_double(v); // the one text of state that reads back exactly
}

std::string hex64(std::uint64_t v) {
    static constexpr char digits[] = "0123456789abcdef";
    std::string out(16, '0');
    for (int i = 15; i >= 0; --i, v >>= 4)
        out[static_cast<std::size_t>(i)] = digits[v & 0xf];
    return out;
}

bool lower_hex(std::string_view s) {
    for (const char c : s)
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f')))
            return false;
    return true;
}

// A game by its own name only, not by the other names a player may type ("10-ball" for
// 10ball): one game, one text.
std::optional<GameType> game_of(std::string_view word) {
    const auto game = parse_game_type(std::string(word));
    if (!game || word != game_type_name(*game))
        return std::nullopt;
    return game;
}

std::string seat_words(const SeatView& seat) {
    return std::string(seat_kind_name(seat.kind)) + " " +
           (seat.kind == SeatKind::empty ? "-" : encode_field(seat.name));
}

// Splits a line into its first `count` fields and, with `rest`, the remainder after the
// space that ends field `count` (the rest of the line, possibly empty).
class Fields {
public:
    explicit Fields(std::string_view line) : line_(line) {}

    // The next space-separated field; empty at the end of the line (or for an empty field,
    // which no message has: an empty result always means a refusal).
    std::string_view next() {
        if (pos_ > line_.size())
            return {};
        const std::size_t space = line_.find(' ', pos_);
        const std::size_t end = space == std::string_view::npos ? line_.size() : space;
        const std::string_view field = line_.substr(pos_, end - pos_);
        pos_ = end + 1;
        return field;
    }
    // Everything after the fields read so far; nothing when the line ended without a space.
    std::optional<std::string_view> rest() {
        if (pos_ > line_.size())
            return std::nullopt;
        const std::string_view r = line_.substr(pos_);
        pos_ = line_.size() + 1;
        return r;
    }
    bool done() const { return pos_ > line_.size(); }

private:
    std::string_view line_;
    std::size_t pos_ = 0;
};

// Field readers: each throws nothing; a failure is reported through `ok`.
class Reader {
public:
    explicit Reader(std::string_view line) : fields_(line) {}

    std::string_view word() {
        const std::string_view w = fields_.next();
        if (w.empty())
            fail("a field is missing or empty");
        return w;
    }
    int integer(int low, int high, const char* what) {
        const std::string_view w = word();
        // One value, one text: no sign, no leading zero, no spaces.
        const auto v = parse_canonical_integer(w);
        if (!ok_)
            return low;
        if (!v || *v < low || *v > high) {
            fail(std::string(what) + " must be a whole number from " + std::to_string(low) +
                 " to " + std::to_string(high));
            return low;
        }
        return static_cast<int>(*v);
    }
    std::size_t count(const char* what) {
        return static_cast<std::size_t>(integer(0, 1'000'000'000, what));
    }
    double real(double low, double high, const char* what) {
        const std::string_view w = word();
        const auto v = parse_canonical_double(w);
        if (!ok_)
            return 0;
        if (!v || !std::isfinite(*v) || *v < low || *v > high) {
            fail(std::string(what) + " must be a number from " + number(low) + " to " +
                 number(high) + ", written as the hall writes it");
            return 0;
        }
        return *v;
    }
    std::uint64_t hash() {
        const std::string_view w = word();
        if (!ok_)
            return 0;
        if (w.size() != 16 || !lower_hex(w)) {
            fail("a hash is 16 lower-case hex digits");
            return 0;
        }
        std::uint64_t v = 0;
        std::from_chars(w.data(), w.data() + w.size(), v, 16);
        return v;
    }
    std::string text(const char* what) {
        const std::string_view w = word();
        if (!ok_)
            return {};
        auto decoded = decode_field(w);
        if (!decoded) {
            fail(std::string(what) + " is not well encoded");
            return {};
        }
        return *decoded;
    }
    std::string name() {
        std::string n = text("a name");
        if (ok_ && !valid_player_name(n))
            fail("a name is 1 to " + std::to_string(max_player_name_bytes) +
                 " bytes of text, no control characters, no space at an end");
        return n;
    }
    SeatView seat_view() {
        SeatView seat;
        const std::string_view kind = word();
        if (!ok_)
            return seat;
        const std::optional<SeatKind> known = parse_name(seat_kind_names, kind);
        if (!known) {
            fail("a seat is empty, player, away or computer");
            return seat;
        }
        seat.kind = *known;
        if (seat.kind == SeatKind::empty) {
            if (word() != "-")
                fail("an empty seat's name is -");
        } else {
            seat.name = name();
        }
        return seat;
    }
    Assist assist() {
        const std::string_view w = word();
        if (!ok_)
            return Assist::standard;
        const std::optional<Assist> a = parse_assist(w);
        if (!a)
            fail("an assist is guided, standard or pro");
        return a.value_or(Assist::standard);
    }
    Strike strike() {
        Strike s;
        s.angle_deg = real(-720, 720, "an angle");
        s.speed = real(0, max_strike_speed, "a speed");
        s.side = real(-0.5, 0.5, "a side offset");
        s.follow = real(-0.5, 0.5, "a follow offset");
        s.elevation_deg = real(0, max_cue_elevation_deg, "an elevation");
        return s;
    }
    std::optional<std::string_view> rest() {
        auto r = fields_.rest();
        if (!r)
            fail("a field is missing");
        return r;
    }
    RecordedAction action() {
        const auto r = rest();
        if (!ok_)
            return {};
        auto parsed = parse_action(*r);
        if (const auto* e = std::get_if<RecordError>(&parsed)) {
            fail("bad action: " + e->message);
            return {};
        }
        // As a record of version 6 holds it: one text per action.
        if (const std::string written = format_action(std::get<RecordedAction>(parsed));
            *r != written) {
            fail("bad action: it is written '" + written + "'");
            return {};
        }
        return std::get<RecordedAction>(parsed);
    }
    // True while fields are left to read.
    bool more() const { return !fields_.done(); }
    // The whole line was read.
    void end() {
        if (ok_ && !fields_.done())
            fail("too many fields");
    }
    void fail(std::string why) {
        if (ok_)
            why_ = std::move(why);
        ok_ = false;
    }
    bool ok() const { return ok_; }
    const std::string& why() const { return why_; }

private:
    Fields fields_;
    bool ok_ = true;
    std::string why_;
};

std::optional<ProtocolError> check_line(std::string_view line) {
    if (line.size() + 1 > max_line_bytes)
        return ProtocolError{ErrorCode::too_long,
                             "a line is at most " + std::to_string(max_line_bytes) + " bytes"};
    if (line.find('\n') != std::string_view::npos || line.find('\r') != std::string_view::npos ||
        line.find('\0') != std::string_view::npos)
        return ProtocolError{ErrorCode::syntax, "a line break or NUL inside a line"};
    return std::nullopt;
}

template <class Message> std::variant<Message, ProtocolError> finish(Reader& r, Message message) {
    r.end();
    if (!r.ok())
        return ProtocolError{ErrorCode::syntax, r.why()};
    return message;
}

template <class... Ts> struct Overloaded : Ts... { using Ts::operator()...; };
template <class... Ts> Overloaded(Ts...) -> Overloaded<Ts...>;

std::string strike_words(const Strike& s) {
    return number(s.angle_deg) + " " + number(s.speed) + " " + number(s.side) + " " +
           number(s.follow) + " " + number(s.elevation_deg);
}

} // namespace

const char* error_code_name(ErrorCode code) {
    return name_of(error_code_names, code, "internal"); // a code the client knows
}

std::optional<ErrorCode> parse_error_code(std::string_view name) {
    return parse_name(error_code_names, name);
}

const char* seat_kind_name(SeatKind kind) {
    return name_of(seat_kind_names, kind, "empty");
}

const char* table_state_name(TableState state) {
    return name_of(table_state_names, state, "waiting");
}

std::string encode_field(std::string_view text) {
    static constexpr char digits[] = "0123456789ABCDEF";
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (needs_escape(byte)) {
            out += '%';
            out += digits[byte >> 4];
            out += digits[byte & 0xf];
        } else {
            out += c;
        }
    }
    return out;
}

std::optional<std::string> decode_field(std::string_view field) {
    std::string out;
    out.reserve(field.size());
    for (std::size_t i = 0; i < field.size(); ++i) {
        const auto byte = static_cast<unsigned char>(field[i]);
        if (byte != '%') {
            if (needs_escape(byte))
                return std::nullopt;
            out += field[i];
            continue;
        }
        if (i + 2 >= field.size())
            return std::nullopt;
        unsigned value = 0;
        for (std::size_t k = 1; k <= 2; ++k) {
            const char h = field[i + k];
            value <<= 4;
            if (h >= '0' && h <= '9')
                value |= static_cast<unsigned>(h - '0');
            else if (h >= 'A' && h <= 'F')
                value |= static_cast<unsigned>(h - 'A' + 10);
            else
                return std::nullopt;
        }
        // One text, one encoding: only the bytes that must be escaped may be.
        if (!needs_escape(static_cast<unsigned char>(value)))
            return std::nullopt;
        out += static_cast<char>(value);
        i += 2;
    }
    return out;
}

bool valid_chat_text(std::string_view text) {
    const std::optional<std::size_t> chars = printable_characters(text);
    return chars && *chars >= 1 && *chars <= max_chat_chars;
}

std::string format_client(const ClientMessage& message) {
    std::string line =
        std::visit(Overloaded{
                       [](const Hello& m) {
                           return "hello " + std::to_string(m.version) + " " +
                                  (m.token.empty() ? std::string("-") : m.token) + " " +
                                  encode_field(m.name);
                       },
                       [](const Create& m) {
                           return std::string("create ") + game_type_name(m.game) + " " +
                                  table_size_name(m.size) + " " + std::to_string(m.race_to) + " " +
                                  assist_name(m.assist);
                       },
                       [](const Sit& m) {
                           return "sit " + std::to_string(m.table) + " " + std::to_string(m.seat);
                       },
                       [](const Watch& m) { return "watch " + std::to_string(m.table); },
                       [](const Leave&) { return std::string("leave"); },
                       [](const Act& m) { return "act " + format_action(m.action); },
                       [](const NextRack&) { return std::string("next-rack"); },
                       [](const Aim& m) { return "aim " + strike_words(m.strike); },
                       [](const Chat& m) { return "chat " + encode_field(m.text); },
                       [](const SeatComputer& m) {
                           return "computer " + std::to_string(m.seat) + " " +
                                  (m.level ? level_name(*m.level) : "none");
                       },
                       [](const Sync& m) {
                           return m.seq ? "sync " + std::to_string(*m.seq) + " " + hex64(m.hash)
                                        : std::string("sync");
                       },
                       [](const Ping&) { return std::string("ping"); },
                       [](const Who&) { return std::string("who"); },
                   },
                   message);
    return line + "\n";
}

std::string format_server(const ServerMessage& message) {
    std::string line = std::visit(
        Overloaded{
            [](const Welcome& m) { return "welcome " + std::to_string(m.version) + " " + m.token; },
            [](const Error& m) {
                return std::string("error ") + error_code_name(m.code) + " " + m.text;
            },
            [](const LobbyBegin&) { return std::string("lobby-begin"); },
            [](const TableView& m) {
                return "table " + std::to_string(m.number) + " " + game_type_name(m.game) + " " +
                       table_size_name(m.size) + " " + std::to_string(m.race_to) + " " +
                       assist_name(m.assist) + " " + table_state_name(m.state) + " " +
                       seat_words(m.seats[0]) + " " + seat_words(m.seats[1]) + " " +
                       std::to_string(m.spectators);
            },
            [](const PlayerView& m) {
                return "player " + encode_field(m.name) + " " + std::to_string(m.table) + " " +
                       std::to_string(m.seat);
            },
            [](const LobbyEnd&) { return std::string("lobby-end"); },
            [](const Created& m) { return "created " + std::to_string(m.table); },
            [](const Joined& m) {
                return "joined " + std::to_string(m.table) + " " + std::to_string(m.seat);
            },
            [](const Left& m) { return "left " + std::to_string(m.table); },
            [](const Yours& m) {
                return "yours " + std::to_string(m.table) + " " + std::to_string(m.seat);
            },
            [](const RecordLine& m) { return "record " + std::to_string(m.table) + " " + m.text; },
            [](const RecordEnd& m) {
                return "record-end " + std::to_string(m.table) + " " + std::to_string(m.seq) + " " +
                       hex64(m.hash);
            },
            [](const SeatChange& m) {
                return "seat " + std::to_string(m.table) + " " + std::to_string(m.seat) + " " +
                       seat_words(m.view);
            },
            [](const ActionDone& m) {
                return "action " + std::to_string(m.table) + " " + std::to_string(m.seq) + " " +
                       hex64(m.hash) + " " + format_action(m.action);
            },
            [](const AimShown& m) {
                return "aim " + std::to_string(m.table) + " " + std::to_string(m.seat) + " " +
                       strike_words(m.strike);
            },
            [](const ChatShown& m) {
                return "chat " + std::to_string(m.table) + " " + encode_field(m.name) + " " +
                       encode_field(m.text);
            },
            [](const Pong&) { return std::string("pong"); },
            [](const WhoLine& m) { return "who " + m.text; },
            [](const WhoEnd&) { return std::string("who-end"); },
        },
        message);
    return line + "\n";
}

std::variant<ClientMessage, ProtocolError> parse_client(std::string_view line) {
    if (auto problem = check_line(line))
        return *problem;
    Reader r(line);
    const std::string_view kind = r.word();
    if (!r.ok())
        return ProtocolError{ErrorCode::syntax, "an empty line"};
    const auto wrap = [](auto parsed) -> std::variant<ClientMessage, ProtocolError> {
        return std::visit([](auto&& v) -> std::variant<ClientMessage, ProtocolError> { return v; },
                          std::move(parsed));
    };

    if (kind == "hello") {
        Hello m;
        // The version comes first and is checked before anything else: a newer client's hello
        // may not read as ours at all.
        const auto version = parse_canonical_integer(r.word());
        if (!r.ok() || !version)
            return ProtocolError{ErrorCode::syntax, "hello VERSION TOKEN|- NAME"};
        if (*version != protocol_version)
            return ProtocolError{ErrorCode::version,
                                 "this hall speaks protocol " + std::to_string(protocol_version)};
        const std::string_view token = r.word();
        if (r.ok() && token != "-") {
            if (token.size() != token_hex_digits || !lower_hex(token))
                r.fail("a token is 32 lower-case hex digits, or -");
            m.token = std::string(token);
        }
        m.name = r.name();
        // A person's name: nothing hidden in it, nothing that turns the lobby's lines around.
        // (Names the server sends are not held to it: a table saved by an older hall may
        // hold one, and its players must still see the lobby.)
        if (r.ok())
            if (auto problem = name_characters_problem(m.name))
                r.fail(std::move(*problem));
        // As wide as the prompt lets a name be, so that the lobby and the table show it whole.
        if (r.ok() && display_width(m.name) > max_name_columns)
            r.fail("a name is at most " + std::to_string(max_name_columns) + " columns wide");
        return wrap(finish(r, m));
    }
    if (kind == "create") {
        Create m;
        const auto game = game_of(r.word());
        const auto size = parse_table_size(r.word());
        if (r.ok() && !game)
            r.fail("a game is 8ball, 8ball-bar, 9ball, 10ball or snooker");
        if (r.ok() && !size)
            r.fail("a table is 7ft, 8ft, 9ft or snooker");
        m.race_to = r.integer(1, max_race_to, "a race");
        m.assist = r.assist();
        if (r.ok()) {
            m.game = *game;
            m.size = *size;
        }
        return wrap(finish(r, m));
    }
    if (kind == "sit") {
        Sit m;
        m.table = r.integer(1, max_table_number, "a table");
        m.seat = r.integer(1, 2, "a seat");
        return wrap(finish(r, m));
    }
    if (kind == "watch") {
        Watch m;
        m.table = r.integer(1, max_table_number, "a table");
        return wrap(finish(r, m));
    }
    if (kind == "act") {
        Act m;
        m.action = r.action();
        if (r.ok() && m.action.kind == RecordedAction::Kind::rack)
            r.fail("a rack is asked with next-rack");
        return wrap(finish(r, m));
    }
    if (kind == "aim") {
        Aim m;
        m.strike = r.strike();
        return wrap(finish(r, m));
    }
    if (kind == "chat") {
        Chat m;
        m.text = r.text("chat");
        if (r.ok() && !valid_chat_text(m.text))
            r.fail("chat is 1 to " + std::to_string(max_chat_chars) +
                   " characters of text, no control characters");
        // What a person says is held to a name's rule: nothing hidden, nothing that turns the
        // line around or breaks it, and something that shows. (Chat the server sends is not:
        // it sent only what it took.)
        if (r.ok())
            if (auto problem = shown_text_problem(m.text, "chat"))
                r.fail(std::move(*problem));
        return wrap(finish(r, m));
    }
    if (kind == "computer") {
        SeatComputer m;
        m.seat = r.integer(1, 2, "a seat");
        const std::string_view level = r.word();
        if (r.ok() && level != "none") {
            m.level = parse_level(std::string(level));
            if (!m.level)
                r.fail("a level is easy, medium, hard, pro or none");
        }
        return wrap(finish(r, m));
    }
    if (kind == "leave")
        return wrap(finish(r, Leave{}));
    if (kind == "next-rack")
        return wrap(finish(r, NextRack{}));
    if (kind == "sync") {
        Sync m;
        if (r.more()) { // what the client's copy came to
            m.seq = r.count("a sequence number");
            m.hash = r.hash();
        }
        return wrap(finish(r, m));
    }
    if (kind == "ping")
        return wrap(finish(r, Ping{}));
    if (kind == "who")
        return wrap(finish(r, Who{}));
    return ProtocolError{ErrorCode::syntax, "unknown message"};
}

std::variant<ServerMessage, ProtocolError> parse_server(std::string_view line) {
    if (auto problem = check_line(line))
        return *problem;
    Reader r(line);
    const std::string_view kind = r.word();
    if (!r.ok())
        return ProtocolError{ErrorCode::syntax, "an empty line"};
    const auto wrap = [](auto parsed) -> std::variant<ServerMessage, ProtocolError> {
        return std::visit([](auto&& v) -> std::variant<ServerMessage, ProtocolError> { return v; },
                          std::move(parsed));
    };
    const auto raw_text = [&r]() {
        const auto rest = r.rest();
        if (!r.ok())
            return std::string();
        if (has_control(*rest))
            r.fail("control characters in text");
        return std::string(*rest);
    };

    if (kind == "welcome") {
        Welcome m;
        const auto version = parse_canonical_integer(r.word());
        if (!r.ok() || !version)
            return ProtocolError{ErrorCode::syntax, "welcome VERSION TOKEN"};
        if (*version != protocol_version)
            return ProtocolError{ErrorCode::version,
                                 "this client speaks protocol " + std::to_string(protocol_version)};
        m.token = std::string(r.word());
        if (r.ok() && (m.token.size() != token_hex_digits || !lower_hex(m.token)))
            r.fail("a token is 32 lower-case hex digits");
        return wrap(finish(r, m));
    }
    if (kind == "error") {
        Error m;
        const auto code = parse_error_code(r.word());
        if (r.ok() && !code)
            r.fail("unknown error code");
        if (code)
            m.code = *code;
        m.text = raw_text();
        return wrap(finish(r, m));
    }
    if (kind == "lobby-begin")
        return wrap(finish(r, LobbyBegin{}));
    if (kind == "lobby-end")
        return wrap(finish(r, LobbyEnd{}));
    if (kind == "pong")
        return wrap(finish(r, Pong{}));
    if (kind == "who-end")
        return wrap(finish(r, WhoEnd{}));
    if (kind == "who")
        return wrap(finish(r, WhoLine{raw_text()}));
    if (kind == "table") {
        TableView m;
        m.number = r.integer(1, max_table_number, "a table");
        const auto game = game_of(r.word());
        const auto size = parse_table_size(r.word());
        if (r.ok() && (!game || !size))
            r.fail("unknown game or table size");
        if (r.ok()) {
            m.game = *game;
            m.size = *size;
        }
        m.race_to = r.integer(1, max_race_to, "a race");
        m.assist = r.assist();
        const std::string_view state = r.word();
        const std::optional<TableState> known = parse_name(table_state_names, state);
        if (known)
            m.state = *known;
        else if (r.ok())
            r.fail("a state is waiting, playing or over");
        m.seats[0] = r.seat_view();
        m.seats[1] = r.seat_view();
        m.spectators = r.integer(0, 1'000'000, "a spectator count");
        return wrap(finish(r, m));
    }
    if (kind == "player") {
        PlayerView m;
        m.name = r.name();
        m.table = r.integer(0, max_table_number, "a table");
        m.seat = r.integer(0, 2, "a seat");
        if (r.ok() && m.table == 0 && m.seat != 0)
            r.fail("no seat in the lobby");
        return wrap(finish(r, m));
    }
    if (kind == "created") {
        Created m;
        m.table = r.integer(1, max_table_number, "a table");
        return wrap(finish(r, m));
    }
    if (kind == "joined") {
        Joined m;
        m.table = r.integer(1, max_table_number, "a table");
        m.seat = r.integer(0, 2, "a seat");
        return wrap(finish(r, m));
    }
    if (kind == "left") {
        Left m;
        m.table = r.integer(1, max_table_number, "a table");
        return wrap(finish(r, m));
    }
    if (kind == "yours") {
        Yours m;
        m.table = r.integer(1, max_table_number, "a table");
        m.seat = r.integer(1, 2, "a seat");
        return wrap(finish(r, m));
    }
    if (kind == "record") {
        RecordLine m;
        m.table = r.integer(1, max_table_number, "a table");
        m.text = raw_text();
        return wrap(finish(r, m));
    }
    if (kind == "record-end") {
        RecordEnd m;
        m.table = r.integer(1, max_table_number, "a table");
        m.seq = r.count("a sequence number");
        m.hash = r.hash();
        return wrap(finish(r, m));
    }
    if (kind == "seat") {
        SeatChange m;
        m.table = r.integer(1, max_table_number, "a table");
        m.seat = r.integer(1, 2, "a seat");
        m.view = r.seat_view();
        return wrap(finish(r, m));
    }
    if (kind == "action") {
        ActionDone m;
        m.table = r.integer(1, max_table_number, "a table");
        m.seq = r.count("a sequence number");
        if (r.ok() && m.seq == 0)
            r.fail("actions count from 1");
        m.hash = r.hash();
        m.action = r.action();
        return wrap(finish(r, m));
    }
    if (kind == "aim") {
        AimShown m;
        m.table = r.integer(1, max_table_number, "a table");
        m.seat = r.integer(1, 2, "a seat");
        m.strike = r.strike();
        return wrap(finish(r, m));
    }
    if (kind == "chat") {
        ChatShown m;
        m.table = r.integer(1, max_table_number, "a table");
        m.name = r.name();
        m.text = r.text("chat");
        if (r.ok() && !valid_chat_text(m.text))
            r.fail("bad chat text");
        return wrap(finish(r, m));
    }
    return ProtocolError{ErrorCode::syntax, "unknown message"};
}

} // namespace termpool::hall
