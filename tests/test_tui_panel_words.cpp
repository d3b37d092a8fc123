// The panel never cuts a word: at every width from 80 to 250 columns and several heights, for
// pool and snooker views with the longest names a player may type, every word the panel shows
// is one of the words it was given (a name too long for its room is shortened visibly, with an
// ellipsis). A cut word ("122 lef") is not among them and fails the test.
#include <catch2/catch.hpp>
#include <set>
#include <sstream>
#include <string>
#include <termpool/rack.hpp>
#include <termpool/snooker_layout.hpp>
#include <termpool/table_physics.hpp>
#include <vector>

#include "tui/ball_style.hpp"
#include "tui/draw.hpp"
#include "tui/pocket_cells.hpp"
#include "tui/snooker_panel.hpp"
#include "tui/view.hpp"
#include "tui_frames.hpp"
#include <termpool/text_width.hpp>

using namespace termpool;
using namespace termpool::tui;

namespace {

const std::string ellipsis = "\u2026";

// The names of two players who typed all the 20 columns a name may have.
const std::string long_one = "Alexandrina Feathers";
const std::string long_two = "Bartholomew Quincey";

// A word without the punctuation around it ("8-ball," is "8-ball", "(best" is "best").
std::string bare(std::string word) {
    while (!word.empty() && std::string(",;:.()").find(word.back()) != std::string::npos)
        word.pop_back();
    while (!word.empty() && word.front() == '(')
        word.erase(0, 1);
    return word;
}

void add_words(std::set<std::string>& words, const std::string& text) {
    std::istringstream in(text);
    for (std::string w; in >> w;)
        words.insert(bare(w));
}

// Every word the panel may show for `v`: what the view says, and the panel's own words.
std::set<std::string> expected_words(const View& v) {
    std::set<std::string> words;
    for (const std::string& name : v.names)
        add_words(words, name);
    add_words(words, v.message);
    for (const std::string& line : v.chat)
        add_words(words, line);
    add_words(words, game_title(v.game));
    add_words(words, "practice race to " + std::to_string(v.race_to) +
                         " open table solids stripes pocketed foul fouls 2 fouls: a third loses");
    add_words(words, "? help q quit Tab chat leave spin side follow calls a safety the in off "
                     "hitting first is a foul on table A-F=10-15");
    add_words(words, format_offset(v.side) + " " + format_offset(v.follow) + " " +
                         format_elevation(v.elevation_deg, true));
    for (int pocket = 1; pocket <= 6; ++pocket)
        add_words(words, pocket_name(pocket));
    for (int id = 0; id <= 21; ++id) {
        add_words(words, std::to_string(id) + " " + ball_label(id, true, false) + " " +
                             ball_label(id, true, true) + " " +
                             ball_label(id, true, false, BallSet::snooker));
        if (id >= 10 && id <= 15)
            words.insert(ball_label(id, true, false) + "=" + std::to_string(id));
    }
    for (int p = 0; p < 2; ++p)
        add_words(words, std::to_string(v.racks_won[p]) + " " + std::to_string(v.scores[p]));
    if (v.game == GameType::snooker) {
        add_words(words,
                  frames_text(v) + " " + high_break_text(v, 1) + " " + high_break_text(v, 2));
        add_words(words, snooker_status(v));
        for (int reds = 1; reds <= 15; ++reds)
            words.insert(ball_label(1, true, false, BallSet::snooker) + "x" + std::to_string(reds));
    }
    // The spin face's centre and tip, and the shooter's mark.
    add_words(words, "\u00B7 + \u25B6");
    return words;
}

// A word shortened on purpose: a name's start and an ellipsis.
bool shortened_name(const std::string& word, const View& v) {
    if (word.size() <= ellipsis.size() ||
        word.compare(word.size() - ellipsis.size(), ellipsis.size(), ellipsis) != 0)
        return false;
    const std::string start = word.substr(0, word.size() - ellipsis.size());
    std::set<std::string> name_words;
    for (const std::string& name : v.names)
        add_words(name_words, name);
    for (const std::string& w : name_words)
        if (w.compare(0, start.size(), start) == 0)
            return true;
    return false;
}

// A message or a chat line cut short at the end of its rows, visibly: a whole word of it and
// an ellipsis.
bool message_cut_visibly(const std::string& word, const View& v) {
    if (word.size() < ellipsis.size() ||
        word.compare(word.size() - ellipsis.size(), ellipsis.size(), ellipsis) != 0)
        return false;
    std::set<std::string> message_words;
    add_words(message_words, v.message);
    for (const std::string& line : v.chat)
        add_words(message_words, line);
    const std::string start = word.substr(0, word.size() - ellipsis.size());
    return start.empty() || message_words.count(bare(start)) > 0;
}

// The panel's rows as text.
std::vector<std::string> panel_rows(const Grid& g, const Layout& l) {
    std::vector<std::string> rows;
    for (int y = l.panel_y; y < std::min(g.height, l.panel_y + l.panel_height); ++y) {
        std::string row;
        for (int x = l.panel_x; x < std::min(g.width, l.panel_x + l.panel_width); ++x)
            row += g.at(x, y).glyph.empty() ? "" : g.at(x, y).glyph;
        rows.push_back(row);
    }
    return rows;
}

// The words of the panel of `v` at `w` x `h` that are not whole words it was given.
std::vector<std::string> cut_words(const View& v, int w, int h) {
    const Layout l = make_layout(*v.table, w, h);
    const Grid g = render(v, l, {256, true}, w, h);
    const std::set<std::string> expected = expected_words(v);
    std::vector<std::string> cut;
    for (const std::string& row : panel_rows(g, l)) {
        std::istringstream in(row);
        for (std::string word; in >> word;)
            if (!expected.count(bare(word)) && !shortened_name(word, v) &&
                !message_cut_visibly(word, v))
                cut.push_back(word + "  (in \"" + row + "\")");
    }
    return cut;
}

// A foul's message with the computer's choice after it, as a player met it at 80x24.
const std::string long_foul_message =
    "Foul and a miss: in-off \u2014 4 points to CPU (hard); CPU (hard) chooses. CPU (hard) "
    "chooses: put the offender back in, the cue ball in the D; Ann has ball in hand in the D";

const PhysicsParams snooker_params = physics_for_table(TableSize::snooker);
const Table snooker_table = make_table(TableSize::snooker, snooker_params.ball_radius);
const Table pool_table = make_table(TableSize::nine_foot);

// The panel of `v` (on its table) at `w` x `h`, a row a line; the layout must fit.
std::string panel_text(const View& v, int w, int h) {
    const Layout l = make_layout(*v.table, w, h);
    REQUIRE(l.fits);
    std::string panel;
    for (const std::string& row : panel_rows(render(v, l, {256, true}, w, h), l))
        panel += row + "\n";
    return panel;
}

// A snooker match late in a frame: a break of 122 on a colour, the black proposed.
View snooker_view() {
    View v;
    v.table = &snooker_table;
    v.balls = make_rack(snooker_table, snooker_params, RackType::snooker, 3);
    v.ball_radius = snooker_params.ball_radius;
    v.game = GameType::snooker;
    v.names[0] = long_one;
    v.names[1] = long_two;
    v.shooter = 1;
    v.scores[0] = 122;
    v.scores[1] = 103;
    v.current_break = 122;
    v.highest_break[0] = 122;
    v.highest_break[1] = 56;
    v.ball_on = BallOn::colour;
    v.nominated = snooker_black;
    v.points_remaining = 122;
    v.best_of = 35;
    v.racks_won[0] = 17;
    v.racks_won[1] = 16;
    v.message = long_one + " scores 1 and plays on";
    v.aiming = true;
    return v;
}

// 8-ball in a race to 15, both groups taken, a long verdict and a call.
View eight_ball_view() {
    View v = test::crowded_view(pool_table);
    v.names[0] = long_one;
    v.names[1] = long_two;
    v.race_to = 15;
    v.racks_won[0] = 14;
    v.racks_won[1] = 13;
    v.message = "Foul: wrong ball first \u2014 " + long_two + " has ball in hand";
    return v;
}

// 9-ball: a player on two fouls, at a hall table with its chat.
View nine_ball_view() {
    View v = test::rack_view(pool_table);
    v.game = GameType::nine_ball;
    v.names[0] = long_one;
    v.names[1] = long_two;
    v.fouls[0] = 2;
    v.fouls[1] = 1;
    v.race_to = 9;
    v.racks_won[0] = 8;
    v.racks_won[1] = 8;
    v.message = "Switch player: " + long_one + " to shoot; " + long_one +
                " is on two fouls: a third in a row loses the game";
    v.hall = true;
    v.chat = {long_two + ": good luck", long_one + ": and to you, well played so far"};
    return v;
}

} // namespace

TEST_CASE("the panel never cuts a word, at every width from 80 to 250 columns", "[tui][panel]") {
    struct Case {
        const char* name;
        View view;
    };
    View free_ball = snooker_view();
    free_ball.free_ball = true;
    free_ball.aiming = false;
    free_ball.placing = true;
    free_ball.current_break = 0;
    free_ball.message = "Foul: in-off \u2014 4 points to " + long_one + "; " + long_one +
                        " has ball in hand in the D";
    // Short names too: the players' column is as wide as their lines, not as the status line.
    View short_names = snooker_view();
    short_names.names[0] = "Ann";
    short_names.names[1] = "Bob";
    short_names.message = "Ann scores 1 and plays on";
    // A message longer than its rows at 80x24: cut at a whole word, visibly.
    View long_message = snooker_view();
    long_message.message = long_foul_message;
    const Case cases[] = {{"snooker", snooker_view()},
                          {"snooker, short names", short_names},
                          {"snooker, free ball, placing", free_ball},
                          {"snooker, a long message", long_message},
                          {"8-ball", eight_ball_view()},
                          {"9-ball", nine_ball_view()}};
    // Every failure is gathered, the first few told: a cut at one width is often a cut at many.
    std::vector<std::string> failures;
    for (const Case& c : cases)
        for (const int h : {24, 32, 45, 60, 70})
            for (int w = 80; w <= 250; ++w)
                for (const std::string& word : cut_words(c.view, w, h))
                    failures.push_back(std::string(c.name) + " at " + std::to_string(w) + "x" +
                                       std::to_string(h) + ": " + word);
    std::string first;
    for (std::size_t i = 0; i < std::min<std::size_t>(failures.size(), 8); ++i)
        first += failures[i] + "\n";
    INFO(failures.size() << " cut words, the first:\n" << first);
    CHECK(failures.empty());
}

TEST_CASE("snooker's status line loses its least telling pieces, never a piece cut",
          "[tui][panel][snooker]") {
    View v = snooker_view();
    CHECK(snooker_status(v) == "break 122  on a colour: black  122 left");
    // The points left go first, then the break; what the player is on stays.
    CHECK(snooker_status(v, 37) == "break 122  on a colour: black");
    CHECK(snooker_status(v, 28) == "on a colour: black");
    CHECK(snooker_status(v, 18) == "on a colour: black");
    CHECK(snooker_status(v, 17).empty());
    v.current_break = 0;
    CHECK(snooker_status(v, 30) == "on a colour: black  122 left");
}

TEST_CASE("at 80x24 the snooker panel shows both players, the score and what is on",
          "[tui][panel][snooker]") {
    const std::string panel = panel_text(snooker_view(), 80, 24);
    CAPTURE(panel);
    CHECK(panel.find("Alexandrina") != std::string::npos);
    CHECK(panel.find("Bartholomew") != std::string::npos);
    CHECK(panel.find("122") != std::string::npos);
    CHECK(panel.find("on a colour: black") != std::string::npos);
}

TEST_CASE("a message longer than its rows ends in an ellipsis after a whole word",
          "[tui][panel][snooker]") {
    View v = snooker_view();
    v.message = long_foul_message;
    const std::string panel = panel_text(v, 80, 24);
    CAPTURE(panel);
    // Too long for the rows below the table: its start is shown, its end is marked as left out.
    REQUIRE(panel.find("Foul and a miss") != std::string::npos);
    CHECK(panel.find("has ball in hand in the D") == std::string::npos);
    CHECK(panel.find(ellipsis) != std::string::npos);
    CHECK(cut_words(v, 80, 24).empty());
    // With room for it all, nothing is marked.
    CHECK(panel_text(v, 200, 60).find(ellipsis) == std::string::npos);
}

TEST_CASE("a chat line cut short in the panel ends in an ellipsis, never looks whole",
          "[tui][panel]") {
    View v = nine_ball_view();
    v.message = "Ann to shoot";
    v.chat = {"Ann: bob fell off his chair laughing at that last shot of his"};
    // 60x20: the panel below the table keeps one row for the newest chat line.
    const std::string panel = panel_text(v, 60, 20);
    CAPTURE(panel);
    const std::size_t said = panel.find("Ann: bob");
    REQUIRE(said != std::string::npos);
    CHECK(panel.find("shot of his") == std::string::npos);
    // The chat's last row shown ends in the ellipsis: the only one in the panel (the message is
    // whole), after the chat's start.
    CHECK(panel.find(ellipsis) == panel.rfind(ellipsis));
    CHECK(panel.find(ellipsis, said) != std::string::npos);
    // With room for it, the line is whole and unmarked.
    const std::string roomy = panel_text(v, 200, 60);
    CAPTURE(roomy);
    CHECK(roomy.find("shot of his") != std::string::npos);
    CHECK(roomy.find(ellipsis) == std::string::npos);
}
