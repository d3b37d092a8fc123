// The hall's lobby frame: what a player reads there at the common sizes, and that no size,
// however small or odd, writes outside the grid or loses the keys; and what a hall table's chat
// entry lets through.
#include <catch2/catch.hpp>
#include <string>

#include "match_helpers.hpp"
#include "tui/hall_driver.hpp"
#include "tui/lobby_view.hpp"
#include "tui/terminal.hpp"

using namespace termpool;
using namespace termpool::tui;

namespace {

std::string row_text(const Grid& g, int y) {
    std::string s;
    for (int x = 0; x < g.width; ++x)
        s += g.at(x, y).glyph;
    return s;
}

std::string all_text(const Grid& g) {
    std::string s;
    for (int y = 0; y < g.height; ++y)
        s += row_text(g, y) + "\n";
    return s;
}

LobbyView two_tables() {
    LobbyView v;
    v.name = "Ann";
    hall::TableView first;
    first.number = 1;
    first.state = hall::TableState::waiting;
    first.seats[0] = {hall::SeatKind::player, "Ann"};
    hall::TableView second;
    second.number = 7;
    second.game = GameType::nine_ball;
    second.size = TableSize::seven_foot;
    second.race_to = 5;
    second.state = hall::TableState::playing;
    second.seats[0] = {hall::SeatKind::away, "Bob"};
    second.seats[1] = {hall::SeatKind::computer, "Computer (pro)"};
    second.spectators = 2;
    v.tables = {first, second};
    v.players = {{"Ann", 1, 1}, {"Cid", 7, 0}, {"Dee", 0, 0}};
    v.selected = 1;
    v.message = "Welcome, Ann.";
    return v;
}

} // namespace

TEST_CASE("the lobby names a snooker table whole where it has the Size column",
          "[tui][lobby][snooker]") {
    LobbyView v = two_tables();
    v.tables[1].size = TableSize::snooker;
    const Grid g = render_lobby(v, Capabilities{}, 100, 32);
    const std::string text = all_text(g);
    INFO(text);
    CHECK(text.find("snooker 5") != std::string::npos);
}

TEST_CASE("the lobby gives a snooker match as best of N frames", "[tui][lobby][snooker]") {
    LobbyView v = two_tables();
    v.tables[1].game = GameType::snooker;
    v.tables[1].size = TableSize::snooker;
    v.tables[1].race_to = 3;
    const std::string text = all_text(render_lobby(v, Capabilities{}, 100, 32));
    INFO(text);
    CHECK(text.find("snooker bo5") != std::string::npos);
    // A single frame is 1, as a single game is.
    v.tables[1].race_to = 1;
    CHECK(all_text(render_lobby(v, Capabilities{}, 100, 32)).find("snooker 1") !=
          std::string::npos);
}

TEST_CASE("the lobby's Race column holds a snooker best of 197 and its header lines up",
          "[tui][lobby][snooker]") {
    LobbyView v = two_tables();
    v.tables[1].game = GameType::snooker;
    v.tables[1].size = TableSize::snooker;
    v.tables[1].race_to = 99;
    v.tables[1].assist = Assist::standard;
    const Grid g = render_lobby(v, Capabilities{}, 100, 32);
    INFO(all_text(g));
    std::string header, row;
    for (int y = 0; y < g.height; ++y) {
        const std::string line = row_text(g, y);
        if (line.find("Race") != std::string::npos)
            header = line;
        if (line.find("bo197") != std::string::npos)
            row = line;
    }
    // A space between the race and the assist, and between the assist and the first seat.
    CHECK(row.find("bo197 standard Bob (away)") != std::string::npos);
    // The header's Race, Assist and Seat 1 start where the row's race, assist and first seat do.
    CHECK(header.find("Race") == row.find("bo197"));
    CHECK(header.find("Assist") == row.find("standard"));
    CHECK(header.find("Seat 1") == row.find("Bob (away)"));
}

TEST_CASE("the lobby shows each table's assist", "[tui][lobby]") {
    LobbyView v = two_tables();
    v.tables[0].assist = Assist::guided;
    v.tables[1].assist = Assist::pro;
    const std::string text = all_text(render_lobby(v, Capabilities{}, 100, 32));
    INFO(text);
    CHECK(text.find("guided") != std::string::npos);
    CHECK(text.find("pro ") != std::string::npos);
}

TEST_CASE("the lobby lists the tables, who is where, the message and the keys", "[tui][lobby]") {
    const Capabilities caps;
    for (const auto& [w, h] : {std::pair{80, 24}, std::pair{100, 32}, std::pair{200, 60}}) {
        INFO(w << "x" << h);
        const Grid g = render_lobby(two_tables(), caps, w, h);
        const std::string text = all_text(g);
        INFO(text);
        CHECK(row_text(g, 0).find("termpool hall") != std::string::npos);
        CHECK(row_text(g, 0).find("Ann") != std::string::npos);
        CHECK(row_text(g, 0).find("3 people here") != std::string::npos);
        CHECK(text.find("(empty)") != std::string::npos);
        CHECK(text.find("Bob (away)") != std::string::npos);
        CHECK(text.find("Computer (pro)") != std::string::npos);
        CHECK(text.find("9-ball") != std::string::npos);
        CHECK(text.find("playing") != std::string::npos);
        CHECK(text.find("waiting") != std::string::npos);
        CHECK(text.find("Cid (watching 7)") != std::string::npos);
        CHECK(text.find("Ann (table 1)") != std::string::npos);
        CHECK(text.find("Welcome, Ann.") != std::string::npos);
        CHECK(row_text(g, h - 1).find("c create") != std::string::npos);
        // The marked row (table 7) is reversed, the other is not.
        const std::string seven = row_text(g, 4);
        CHECK(seven.find("Bob (away)") != std::string::npos);
        CHECK(g.at(2, 4).style.reverse);
        CHECK_FALSE(g.at(2, 3).style.reverse);
        if (w >= 90) { // room for the size, the race and the spectators
            CHECK(seven.find("7ft") != std::string::npos);
            CHECK(seven.find(" 5 ") != std::string::npos);
        }
    }
}

TEST_CASE("the lobby at every size from 0x0 to 120x40 stays inside its grid", "[tui][lobby]") {
    LobbyView v = two_tables();
    v.overlay = "A new table\n\ng  game      8-ball\nEnter creates it, Esc goes back";
    for (int i = 0; i < 30; ++i) { // more tables than rows: the list scrolls to the marked one
        hall::TableView t;
        t.number = 10 + i;
        v.tables.push_back(t);
    }
    v.selected = 25;
    for (const bool utf8 : {true, false})
        for (int w = 0; w <= 120; w += 7)
            for (int h = 0; h <= 40; h += 3) {
                Capabilities caps;
                caps.utf8 = utf8;
                INFO(w << "x" << h << (utf8 ? " UTF-8" : " ASCII"));
                const Grid g = render_lobby(v, caps, w, h);
                REQUIRE(g.width == w);
                REQUIRE(g.height == h);
                LobbyView plain = v;
                plain.overlay.clear();
                const Grid list = render_lobby(plain, caps, w, h);
                if (w >= 40 && h >= 10) {
                    CHECK(all_text(g).find("A new table") != std::string::npos);
                    CHECK(all_text(list).find("\n 33 ") != std::string::npos);
                } else if (w >= 40 && h > 0) {
                    CHECK(all_text(g).find("Please enlarge") != std::string::npos);
                }
            }
}

TEST_CASE("a click on the lobby's list picks the table drawn on that row, scrolled or not",
          "[tui][lobby]") {
    LobbyView v = two_tables();
    const Capabilities caps;
    for (int i = 0; i < 40; ++i) {
        hall::TableView t;
        t.number = 100 + i;
        v.tables.push_back(t);
    }
    for (const int selected : {0, 1, 20, 41}) {
        v.selected = selected;
        const Grid g = render_lobby(v, caps, 80, 24);
        for (int y = 0; y < 24; ++y) {
            INFO("selected " << selected << ", row " << y << ": " << row_text(g, y));
            const int index = lobby_table_at(v, 24, y);
            if (index < 0)
                continue;
            const std::string number =
                " " + std::to_string(v.tables[static_cast<std::size_t>(index)].number) + " ";
            CHECK(row_text(g, y).find(number) == 0);
        }
        CHECK(lobby_table_at(v, 24, 0) == -1); // the title
        CHECK(lobby_table_at(v, 24, 2) == -1); // the header
    }
    CHECK(lobby_table_at(v, 5, 3) == -1); // too small to draw a list
}

TEST_CASE("hall table: chat typed at the terminal leaves out what the hall refuses", "[tui]") {
    GameRecord header;
    header.setup.game = GameType::nine_ball;
    header.names[0] = "Ann";
    header.names[1] = "Bob";
    std::vector<std::string> sent;
    TableLink link;
    link.seat = 1;
    link.chat = [&](const std::string& line) {
        sent.push_back(line);
        return true;
    };
    HallDriver driver(test::started(header), link);
    const Layout layout;
    const ScreenFacts screen;
    const auto key = [&](int k) {
        Input in;
        in.kind = Input::Kind::key;
        in.key = k;
        driver.handle(in, layout, screen);
    };
    const auto type = [&](const std::string& text) {
        Input in;
        in.kind = Input::Kind::text;
        in.text = text;
        driver.handle(in, layout, screen);
    };
    key('\t');
    // A direction override, a zero-width space, a line separator and a C1 control are
    // dropped as typed; letters, marks and emoji stay.
    for (const std::string typed : {"g", "\u202E", "g", "\u200B", " ", "\u2028", "\u00e9", "\u0301",
                                    "\xc2\x85", "\U0001F3B1"})
        type(typed);
    key(key_enter);
    REQUIRE(sent.size() == 1);
    CHECK(sent[0] == "gg \u00e9\u0301\U0001F3B1");
    // Nothing but spaces is not sent: Enter closes the line, as an empty one.
    key('\t');
    type(" ");
    type(" ");
    key(key_enter);
    CHECK(sent.size() == 1);
}
