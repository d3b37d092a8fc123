#pragma once
// The message tables below are laid out by hand; clang-format would fold them into prose.
// clang-format off
/// \file
/// The hall's line protocol, version 1: what a client and the server say to each other over
/// the hall's Unix socket. Pure functions, no I/O; both sides use them.
///
/// A message is one line of at most `max_line_bytes` bytes including its '\n'. Fields are
/// separated by single spaces. Text that may hold spaces (a NAME, chat TEXT) is one field,
/// percent-encoded: '%', bytes up to and including ' ', and DEL are written %XX (upper-case
/// hex), so a name or a chat line can never break a line or a field. An ACTION (the record's
/// action line, `format_action`) and a raw TEXT (a record line, an error's words) are the
/// rest of the line, unencoded: they never hold control characters. Every value has one text,
/// and a line that reads is exactly the line its message formats to: numbers are decimal,
/// without '+' or a leading zero ("0" only as itself); doubles are the shortest text that
/// reads back bit for bit (no "-0"); an ACTION is exactly as `format_action` writes it; a GAME
/// is its own name; a NAME in hello holds no invisible or direction character (names the
/// server sends are not held to it). A HASH is 16 lower-case hex digits (`Match::state_hash`);
/// a TOKEN is 32 lower-case hex digits.
///
/// Client to server:
///
///   hello VERSION TOKEN|- NAME        first message; "-" asks for a new token
///   create GAME SIZE RACE ASSIST      a new table: GAME 8ball|8ball-bar|9ball|10ball|snooker,
///                                     SIZE 7ft|8ft|9ft|snooker, RACE 1..99, ASSIST guided|
///                                     standard|pro (both seats' aiming aid)
///   sit TABLE SEAT                    take seat 1 or 2 (or take back one's own away seat)
///   watch TABLE                       follow a table as a spectator
///   leave                             leave the table (a seat in a started game stays, away)
///   act ACTION                        place / shot / choose (choose concede: concede the
///                                     frame, snooker), as `format_action` writes it
///   next-rack                         rack the next rack of a race
///   aim DEG SPEED SIDE FOLLOW ELEV    the shooter's cue as it aims (a Strike, not played)
///   chat TEXT                         to the table: 1..200 characters, no control characters
///   computer SEAT LEVEL|none          seat (or unseat) the computer in an empty seat (a
///                                     player seated at the table only)
///   sync [SEQ HASH]                   send me my table's record again; after a mismatch,
///                                     SEQ and HASH say what my copy came to (it holds SEQ
///                                     actions and hashes HASH), for the server's log
///   ping                              answered by pong
///   who                               the hall's tables, people and connections, for its
///                                     host (`termpool hall who`); may come before hello
///
/// Server to client:
///
///   welcome VERSION TOKEN             hello accepted; keep TOKEN to prove who you are later
///   error CODE TEXT                   a message refused (CODE: see ErrorCode), nothing changed
///   lobby-begin                       a lobby snapshot follows: table and player lines
///   table N GAME SIZE RACE ASSIST STATE KIND1 NAME1 KIND2 NAME2 SPECTATORS
///                                     STATE waiting|playing|over; KIND empty|player|away|
///                                     computer (NAME "-" for an empty seat)
///   player NAME TABLE SEAT            someone in the hall: TABLE 0 in the lobby, SEAT 0
///                                     watching
///   lobby-end                         the snapshot is complete
///   created TABLE                     the table asked for exists
///   joined TABLE SEAT                 you sit (SEAT 1 or 2) or watch (SEAT 0); the record
///                                     follows
///   left TABLE                        you are back in the lobby
///   yours TABLE SEAT                  after welcome: this away seat is yours, sit to play on
///   record TABLE TEXT                 one line of the table's record (`format_record`)
///   record-end TABLE SEQ HASH         the record is complete: SEQ actions, state HASH
///   seat TABLE SEAT KIND NAME         a seat changed (sat, away, back, computer, freed)
///   action TABLE SEQ HASH ACTION      the server applied ACTION as the table's action SEQ
///                                     (from 1); HASH is the state after it
///   aim TABLE SEAT DEG SPEED SIDE FOLLOW ELEV
///                                     the shooter's cue, at most every 50 ms
///   chat TABLE NAME TEXT              a chat line at the table
///   pong                              the answer to ping
///   who TEXT                          one line of the answer to who (no control characters)
///   who-end                           the answer to who is complete
// clang-format on

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <termpool/assist.hpp>
#include <termpool/enum_names.hpp>
#include <termpool/game_registry.hpp>
#include <termpool/level.hpp>
#include <termpool/record.hpp>
#include <termpool/rules.hpp>
#include <termpool/simulator.hpp>
#include <termpool/table.hpp>
#include <variant>

namespace termpool::hall {

/// The protocol version this build speaks; `hello` and `welcome` carry it. Version 2 added the
/// cue's elevation to `aim` (and shots' `elevation` field, from the record's version 3),
/// version 3 the assist to `create` and `table` (and the record's `assist` line, version 5).
inline constexpr int protocol_version = 3;
/// The longest line, in bytes, including its '\n'.
inline constexpr std::size_t max_line_bytes = 4096;
/// The longest chat line, in characters (UTF-8 code points).
inline constexpr std::size_t max_chat_chars = 200;
/// The highest table number.
inline constexpr int max_table_number = 9999;
/// The length of a token, in hex digits.
inline constexpr std::size_t token_hex_digits = 32;

/// Why a message was refused: the CODE field of `error`.
enum class ErrorCode {
    syntax,      ///< "syntax": not a message, or a field out of range
    too_long,    ///< "too-long": a line longer than max_line_bytes (the connection closes)
    version,     ///< "version": another protocol version (the connection closes)
    hello_first, ///< "hello-first": hello must come first, and only once
    full,        ///< "full": the server has all the clients or tables it takes
    no_table,    ///< "no-table": no such table, or you are at none
    seat_taken,  ///< "seat-taken": the seat is someone else's
    not_seated,  ///< "not-seated": only a seated player may do that
    refused,     ///< "refused": the match refused the action (TEXT says why)
    rate,        ///< "rate": too many messages of that kind (chat: one a second)
    replaced,    ///< "replaced": the same token connected again (the connection closes)
    internal,    ///< "internal": the server could not do it (e.g. saving failed)
    name_taken,  ///< "name-taken": someone in the hall has that name (the connection closes)
};

/// The CODE words.
inline constexpr NameRow<ErrorCode> error_code_names[] = {
    {ErrorCode::syntax, "syntax"},
    {ErrorCode::too_long, "too-long"},
    {ErrorCode::version, "version"},
    {ErrorCode::hello_first, "hello-first"},
    {ErrorCode::full, "full"},
    {ErrorCode::no_table, "no-table"},
    {ErrorCode::seat_taken, "seat-taken"},
    {ErrorCode::not_seated, "not-seated"},
    {ErrorCode::refused, "refused"},
    {ErrorCode::rate, "rate"},
    {ErrorCode::replaced, "replaced"},
    {ErrorCode::internal, "internal"},
    {ErrorCode::name_taken, "name-taken"},
};
static_assert(names_in_order(error_code_names));

/// The CODE word of `code` ("internal" for a value out of range).
const char* error_code_name(ErrorCode code);
/// The code named `name`; nothing for an unknown word.
std::optional<ErrorCode> parse_error_code(std::string_view name);

/// Why a line could not be read.
struct ProtocolError {
    ErrorCode code = ErrorCode::syntax; ///< syntax, too_long or version
    std::string text;                   ///< what is wrong, for the error reply
};

// --- client to server ---------------------------------------------------------------------

/// `hello VERSION TOKEN|- NAME`.
struct Hello {
    int version = protocol_version; ///< the client's protocol version
    std::string token;              ///< the client's token, empty for none ("-")
    std::string name;               ///< a valid player name
};
/// `create GAME SIZE RACE ASSIST`.
struct Create {
    GameType game = default_game;          ///< the rules
    TableSize size = TableSize::nine_foot; ///< the table
    int race_to = 1;                       ///< 1 (a single game) to max_race_to
    Assist assist = Assist::standard;      ///< the aiming aid of both seats
};
/// `sit TABLE SEAT`.
struct Sit {
    int table = 1; ///< 1 to max_table_number
    int seat = 1;  ///< 1 or 2
};
/// `watch TABLE`.
struct Watch {
    int table = 1; ///< 1 to max_table_number
};
/// `leave`.
struct Leave {};
/// `act ACTION`: a place, shot or choose action (a rack comes from `next-rack`).
struct Act {
    RecordedAction action; ///< as `parse_action` read it
};
/// `next-rack`.
struct NextRack {};
/// `aim DEG SPEED SIDE FOLLOW ELEV`: the strike as the shooter aims it; each value in the
/// simulator's range (`strike_in_range`).
struct Aim {
    Strike strike; ///< not played, only shown
};
/// `chat TEXT`.
struct Chat {
    std::string text; ///< 1 to max_chat_chars characters of UTF-8, no control characters
};
/// `computer SEAT LEVEL|none`.
struct SeatComputer {
    int seat = 1;               ///< 1 or 2
    std::optional<Level> level; ///< none: give the seat back to people
};
/// `sync [SEQ HASH]`.
struct Sync {
    /// After a mismatch: the actions the client's copy holds (it played action SEQ, or could
    /// not play the next one); nothing for a plain request.
    std::optional<std::size_t> seq;
    std::uint64_t hash = 0; ///< the client's copy's state hash there (with `seq` only)
};
/// `ping`.
struct Ping {};
/// `who`.
struct Who {};

/// Anything a client says.
using ClientMessage = std::variant<Hello, Create, Sit, Watch, Leave, Act, NextRack, Aim, Chat,
                                   SeatComputer, Sync, Ping, Who>;

// --- server to client ---------------------------------------------------------------------

/// Who is in a seat, as others see it.
enum class SeatKind {
    empty,    ///< "empty": free to take
    player,   ///< "player": a person, connected
    away,     ///< "away": a person whose connection dropped; the seat waits for them
    computer, ///< "computer": the server plays it
};

/// The seat kinds' words.
inline constexpr NameRow<SeatKind> seat_kind_names[] = {
    {SeatKind::empty, "empty"},
    {SeatKind::player, "player"},
    {SeatKind::away, "away"},
    {SeatKind::computer, "computer"},
};
static_assert(names_in_order(seat_kind_names));
/// "empty", "player", "away" or "computer".
const char* seat_kind_name(SeatKind kind);

/// A seat as the lobby and the table show it.
struct SeatView {
    SeatKind kind = SeatKind::empty; ///< who sits
    std::string name;                ///< their name; empty for an empty seat
    /// Equal kinds and names.
    bool operator==(const SeatView&) const = default;
};

/// Where a table stands.
enum class TableState {
    waiting, ///< "waiting": a seat is empty
    playing, ///< "playing": both seats taken, the match goes on
    over,    ///< "over": the match is won
};

/// The table states' words.
inline constexpr NameRow<TableState> table_state_names[] = {
    {TableState::waiting, "waiting"},
    {TableState::playing, "playing"},
    {TableState::over, "over"},
};
static_assert(names_in_order(table_state_names));
/// "waiting", "playing" or "over".
const char* table_state_name(TableState state);

/// `welcome VERSION TOKEN`.
struct Welcome {
    int version = protocol_version; ///< the server's protocol version
    std::string token;              ///< the client's token (new, or the one it gave)
};
/// `error CODE TEXT`.
struct Error {
    ErrorCode code = ErrorCode::syntax; ///< why
    std::string text;                   ///< a few words, no control characters
};
/// `lobby-begin`.
struct LobbyBegin {};
/// `table N GAME SIZE RACE ASSIST STATE KIND1 NAME1 KIND2 NAME2 SPECTATORS`.
struct TableView {
    int number = 1;                         ///< 1 to max_table_number
    GameType game = default_game;           ///< the rules
    TableSize size = TableSize::nine_foot;  ///< the table
    int race_to = 1;                        ///< 1 to max_race_to
    Assist assist = Assist::standard;       ///< the aiming aid of both seats
    TableState state = TableState::waiting; ///< where it stands
    SeatView seats[2];                      ///< seat 1 and seat 2
    int spectators = 0;                     ///< how many watch
};
/// `player NAME TABLE SEAT`.
struct PlayerView {
    std::string name; ///< a valid player name
    int table = 0;    ///< 0 in the lobby
    int seat = 0;     ///< 1 or 2 seated, 0 watching (or in the lobby)
};
/// `lobby-end`.
struct LobbyEnd {};
/// `created TABLE`.
struct Created {
    int table = 1; ///< its number
};
/// `joined TABLE SEAT`.
struct Joined {
    int table = 1; ///< the table
    int seat = 0;  ///< 1 or 2 seated, 0 watching
};
/// `left TABLE`.
struct Left {
    int table = 1; ///< the table left
};
/// `yours TABLE SEAT`.
struct Yours {
    int table = 1; ///< the table
    int seat = 1;  ///< the seat kept for this token
};
/// `record TABLE TEXT`: one line of the record, without its newline.
struct RecordLine {
    int table = 1;    ///< the table
    std::string text; ///< the line (may be empty; no control characters)
};
/// `record-end TABLE SEQ HASH`.
struct RecordEnd {
    int table = 1;          ///< the table
    std::size_t seq = 0;    ///< the number of actions in the record
    std::uint64_t hash = 0; ///< Match::state_hash after them
};
/// `seat TABLE SEAT KIND NAME`.
struct SeatChange {
    int table = 1; ///< the table
    int seat = 1;  ///< 1 or 2
    SeatView view; ///< who sits there now
};
/// `action TABLE SEQ HASH ACTION`.
struct ActionDone {
    int table = 1;          ///< the table
    std::size_t seq = 1;    ///< the action's number in the record, from 1
    std::uint64_t hash = 0; ///< Match::state_hash after it
    RecordedAction action;  ///< what was applied (a rack action included)
};
/// `aim TABLE SEAT DEG SPEED SIDE FOLLOW ELEV`.
struct AimShown {
    int table = 1; ///< the table
    int seat = 1;  ///< the shooter
    Strike strike; ///< the cue as it aims
};
/// `chat TABLE NAME TEXT`.
struct ChatShown {
    int table = 1;    ///< the table
    std::string name; ///< who said it
    std::string text; ///< what, as `Chat` allows
};
/// `pong`.
struct Pong {};
/// `who TEXT`: one line of the hall's state for its host.
struct WhoLine {
    std::string text; ///< the line (may be empty; no control characters)
};
/// `who-end`.
struct WhoEnd {};

/// Anything the server says.
using ServerMessage = std::variant<Welcome, Error, LobbyBegin, TableView, PlayerView, LobbyEnd,
                                   Created, Joined, Left, Yours, RecordLine, RecordEnd, SeatChange,
                                   ActionDone, AimShown, ChatShown, Pong, WhoLine, WhoEnd>;

// --- text ---------------------------------------------------------------------------------

/// `text` percent-encoded as one field (see the file comment); never empty for non-empty text.
std::string encode_field(std::string_view text);
/// The text of an encoded field; nothing for a bad escape or a byte that should have been
/// escaped.
std::optional<std::string> decode_field(std::string_view field);
/// True for chat text: valid UTF-8, 1 to max_chat_chars code points, no control characters
/// (C0, DEL, C1).
bool valid_chat_text(std::string_view text);

/// The line of `message`, with its '\n'. Values are written as they are; a caller that built
/// a message from unchecked input should parse what it sends (the server only sends what it
/// validated).
std::string format_client(const ClientMessage& message);
/// The line of `message`, with its '\n'.
std::string format_server(const ServerMessage& message);

/// Reads one client line (without its '\n'), checking every field.
std::variant<ClientMessage, ProtocolError> parse_client(std::string_view line);
/// Reads one server line (without its '\n'), checking every field.
std::variant<ServerMessage, ProtocolError> parse_server(std::string_view line);

} // namespace termpool::hall
