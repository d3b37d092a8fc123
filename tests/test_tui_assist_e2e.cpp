// The assist levels and the call through the real binary in tmux: where each level's turns
// open, what its aid draws (a kick's rebound under guided, a short object line under standard,
// nothing past the first contact under pro), the warning before a foul, a kick called with the
// pocket keys, and the call the panel shows being the one the save records, the computer's too.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <termpool/match.hpp>
#include <termpool/record.hpp>
#include <utility>
#include <variant>

#include "tmux_session.hpp"
#include "tui/aim.hpp"
#include "tui/aim_state.hpp"
#include "tui/cue_ball_spot.hpp"
#include "tui/pocket_cells.hpp"
#include "tui/view.hpp"

using namespace termpool;
using tmux_session::file_text;
using tmux_session::game_command;
using tmux_session::ScratchDir;
using tmux_session::Tmux;

namespace {

// A 10-ball game after the break and a foul, the cue ball in hand put at a chosen spot: the
// record to resume, the lowest ball (the one legal first) and the ball beside the cue ball.
struct Scenario {
    GameRecord record;
    int target = 0;                    // the lowest ball
    int blocker = 0;                   // kick: the ball between the cue ball and the target
    Vec2 cue;                          // where the cue ball was put
    std::pair<int, int> hover{-1, -1}; // cut: the cell whose pointer aims the cut
};

constexpr int width = 100, height = 32;

// The cell of table point `p` at 100x32.
std::pair<int, int> cell_of(const Table& table, Vec2 p) {
    const tui::Layout l = tui::make_layout(table, width, height);
    double col, row;
    tui::to_cell(l, table.width, p, col, row);
    return {static_cast<int>(std::floor(col)), static_cast<int>(std::floor(row))};
}

const Ball* ball_of(const Game& g, int id) {
    for (const Ball& b : g.balls())
        if (b.id == id && b.state != MotionState::pocketed)
            return &b;
    return nullptr;
}

// The aim state of the turn at `cue` as the game opens it under `assist`.
tui::AimState opened(const Game& g, Vec2 cue, const std::vector<int>& legal, Assist assist) {
    std::vector<Ball> balls = g.balls();
    for (Ball& b : balls)
        if (b.id == 0) {
            b.position = cue;
            b.state = MotionState::stationary;
        }
    tui::AimState aim;
    aim.assist = assist;
    aim.new_turn();
    aim.aim_at_target(
        tui::rank_openings(g.table(), balls, g.params().ball_radius, cue, legal, assist));
    aim.update_preview(g.table(), g.params(), balls, false, [](int) { return true; });
    return aim;
}

// 10-ball from `seed`: the break from the head spot, then, shot by shot, a soft tap that meets
// nothing (a foul) until a player has the cue ball in hand anywhere; the spot is then chosen by
// `pick` (nothing: no spot suits, try another seed).
template <class Pick> std::optional<Scenario> ten_ball_in_hand(std::uint64_t seed, Pick pick) {
    GameRecord header;
    header.setup.game = GameType::ten_ball;
    header.seed = seed;
    header.names[0] = "Ann";
    header.names[1] = "Bob";
    auto started = Match::start(header, seed + 1);
    Match& m = std::get<Match>(started);
    const Table& table = m.game().table();
    REQUIRE(m.place(1, table.head_spot()) == MatchError::none);
    REQUIRE(std::holds_alternative<PlayedShot>(m.shoot(1, Strike{12, 0}, {})));
    for (int n = 0; n < 10; ++n) {
        const PendingAction p = m.pending();
        if (p.kind == Pending::over)
            return std::nullopt;
        if (p.kind == Pending::choose) {
            m.choose(p.player, m.game().choices().front());
            continue;
        }
        if (p.kind == Pending::place) {
            if (p.ball_in_hand != BallInHand::anywhere)
                return std::nullopt;
            const std::optional<Scenario> s = pick(m.game());
            if (!s)
                return std::nullopt;
            Scenario out = *s;
            REQUIRE(m.place(p.player, out.cue) == MatchError::none);
            out.record = m.record();
            return out;
        }
        // A tap towards the farthest rail: 0.3 m/s stops long before it.
        const Ball* cue = ball_of(m.game(), 0);
        REQUIRE(cue);
        const double deg = cue->position.x < table.length / 2 ? 180 : 0;
        REQUIRE(std::holds_alternative<PlayedShot>(m.shoot(p.player, Strike{0.3, deg}, {})));
    }
    return std::nullopt;
}

// The lowest ball hidden behind another from the cue ball's spot: only a kick reaches it, and
// the shot the guided aid draws meets it off the rail.
std::optional<Scenario> kick_spot(const Game& g) {
    const std::vector<int> legal = g.legal_targets();
    const Ball* target = legal.empty() ? nullptr : ball_of(g, legal.front());
    if (!target)
        return std::nullopt;
    for (const Ball& b : g.balls()) {
        if (b.id == 0 || b.id == target->id || b.id > 9 || b.state == MotionState::pocketed)
            continue;
        for (const double d : {0.1, 0.13, 0.16, 0.2}) {
            const Vec2 cue = b.position + normalized(b.position - target->position) * d;
            if (!g.legal_placement(cue))
                continue;
            const tui::AimState aim = opened(g, cue, legal, Assist::guided);
            if (aim.target_line == tui::TargetLine::kick && aim.preview_ball == target->id &&
                aim.full_preview.cushion >= 0 && aim.full_preview.kick_leg.size() >= 2)
                return Scenario{{}, target->id, b.id, cue};
        }
    }
    return std::nullopt;
}

// The first ball the cue ball placed at `cue` meets when struck as `strike`, -1 for none.
int first_contact(const Game& g, Vec2 cue, const Strike& strike) {
    Game played = g;
    REQUIRE(played.place_cue_ball(cue));
    return played.play(strike, {}).first_contact;
}

// A kick the mirror aim misses: the lowest ball hidden as for kick_spot, and the strike at the
// mirror aim in the rail, at the opening's power, meets another ball first or none.
std::optional<Scenario> missed_kick_spot(const Game& g) {
    const std::optional<Scenario> s = kick_spot(g);
    if (!s)
        return std::nullopt;
    const auto mirror = tui::rank_openings(g.table(), g.balls(), g.params().ball_radius, s->cue,
                                           g.legal_targets(), Assist::standard);
    const tui::AimState aim = opened(g, s->cue, g.legal_targets(), Assist::standard);
    if (mirror.empty() || mirror[0].line != tui::TargetLine::kick)
        return std::nullopt;
    Strike strike = aim.set_strike(false);
    strike.angle_deg = mirror[0].aim_deg;
    if (first_contact(g, s->cue, strike) == s->target)
        return std::nullopt;
    return s;
}

// The lowest ball in plain view, half a metre away: a cell near it whose pointer aims a cut
// of 15 to 45 degrees that meets it first, its object ball's line running on a long way.
std::optional<Scenario> cut_spot(const Game& g) {
    const std::vector<int> legal = g.legal_targets();
    const Ball* target = legal.empty() ? nullptr : ball_of(g, legal.front());
    if (!target)
        return std::nullopt;
    const tui::Layout l = tui::make_layout(g.table(), width, height);
    const double R = g.params().ball_radius;
    for (int k = 0; k < 36; ++k) {
        const double a = k * 10 * 3.14159265358979 / 180;
        const Vec2 cue = target->position + Vec2{std::cos(a), std::sin(a)} * 0.5;
        if (!g.legal_placement(cue))
            continue;
        const auto [tx, ty] = cell_of(g.table(), target->position);
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -2; dx <= 2; ++dx) {
                tui::AimState aim = opened(g, cue, legal, Assist::guided);
                aim.aim_deg = tui::aim_from_pointer(
                    cue, tui::from_cell(l, g.table().width, tx + dx, ty + dy));
                std::vector<Ball> balls = g.balls();
                for (Ball& b : balls)
                    if (b.id == 0)
                        b.position = cue;
                aim.update_preview(g.table(), g.params(), balls, false, [](int) { return true; });
                const tui::AimPreview& p = aim.full_preview;
                if (p.object_ball != target->id || p.object_path.size() < 2 || !p.has_ghost)
                    continue;
                const Vec2 line = p.object_path[1] - p.object_path[0];
                const Vec2 in = normalized(p.ghost - p.cue_path.front());
                const double cut =
                    std::acos(std::clamp(dot(in, normalized(line)), -1.0, 1.0)) * 180 / 3.14159265;
                if (cut > 15 && cut < 45 && length(line) > 0.4 && length(line) > 12 * R)
                    return Scenario{{}, target->id, 0, cue, {tx + dx, ty + dy}};
            }
    }
    return std::nullopt;
}

template <class Pick> Scenario find_scenario(Pick pick) {
    for (std::uint64_t seed = 1; seed < 60; ++seed)
        if (auto s = ten_ball_in_hand(seed, pick))
            return *s;
    FAIL("no seed gives the position wanted");
    return {};
}

// The record with `assist`, written to `path`.
void write_save(const GameRecord& record, Assist assist, const std::string& path) {
    GameRecord r = record;
    r.assist = assist;
    std::ofstream(path) << format_record(r);
}

// The screen's rows split into cells (each a UTF-8 glyph of one column).
std::vector<std::vector<std::string>> cells_of(const std::string& screen) {
    std::vector<std::vector<std::string>> rows;
    std::size_t start = 0;
    while (start < screen.size()) {
        const std::size_t end = std::min(screen.find('\n', start), screen.size());
        std::vector<std::string> row;
        const std::string line = screen.substr(start, end - start);
        for (std::size_t i = 0; i < line.size();) {
            const auto c = static_cast<unsigned char>(line[i]);
            const std::size_t n = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 1;
            row.push_back(line.substr(i, n));
            i += n;
        }
        rows.push_back(row);
        start = end + 1;
    }
    return rows;
}

// The dots of a Braille glyph (U+2800 + mask), 0 for any other glyph.
int braille_dots(const std::string& glyph) {
    if (glyph.size() != 3 || glyph[0] != '\xE2' || (glyph[1] & 0xFC) != 0xA0)
        return 0;
    return ((glyph[1] & 0x03) << 6) | (glyph[2] & 0x3F);
}

// The dots of the table's own marks (the head string) at cell x, y of a 100x32 frame.
int table_dots(const Table& table, int x, int y) {
    static const Table* drawn = nullptr;
    static tui::Grid grid(1, 1);
    if (drawn != &table) {
        tui::View v;
        v.table = &table;
        grid = tui::render(v, tui::make_layout(table, width, height), {256, true}, width, height);
        drawn = &table;
    }
    return x < grid.width && y < grid.height ? braille_dots(grid.at(x, y).glyph) : 0;
}

// The cells where the aid draws dots that neither the plain aim line (the aid turned off) nor
// the table's marks do: what the aid shows beyond the cue's own line, the ghost ball and the
// lines after a contact. The cue ball's way to its first contact lies on the aim line.
std::set<std::pair<int, int>> aid_cells(const Table& table, const std::string& with,
                                        const std::string& without) {
    const auto a = cells_of(with), b = cells_of(without);
    std::set<std::pair<int, int>> out;
    for (std::size_t y = 0; y < a.size(); ++y)
        for (std::size_t x = 0; x < a[y].size(); ++x) {
            const int plain = y < b.size() && x < b[y].size() ? braille_dots(b[y][x]) : 0;
            const int marks = table_dots(table, static_cast<int>(x), static_cast<int>(y));
            if ((braille_dots(a[y][x]) & ~plain & ~marks) != 0)
                out.insert({static_cast<int>(x), static_cast<int>(y)});
        }
    return out;
}

// The cells outside the box around `a` and `b` widened by `margin` columns (half as many rows).
int cells_outside(const std::set<std::pair<int, int>>& cells, std::pair<int, int> a,
                  std::pair<int, int> b, int margin) {
    const int x0 = std::min(a.first, b.first) - margin, x1 = std::max(a.first, b.first) + margin;
    const int y0 = std::min(a.second, b.second) - (margin + 1) / 2,
              y1 = std::max(a.second, b.second) + (margin + 1) / 2;
    int n = 0;
    for (const auto& [x, y] : cells)
        if (x < x0 || x > x1 || y < y0 || y > y1)
            ++n;
    return n;
}

// The cells, for a failure's message.
std::string cells_text(const std::set<std::pair<int, int>>& cells) {
    std::string out;
    for (const auto& [x, y] : cells)
        out += " " + std::to_string(x) + "," + std::to_string(y);
    return out;
}

// Resumes `save` in tmux and returns the aid's cells (aid_cells) at the opening aim, or with the
// pointer over `hover` when given.
std::set<std::pair<int, int>> opening_aid(const Tmux& t, const ScratchDir& dir, const Table& table,
                                          const std::string& save,
                                          std::pair<int, int> hover = {-1, -1}) {
    t.start(game_command(dir, "--resume " + save), width, height);
    REQUIRE(t.wait_for_text("[ shoot ]"));
    if (hover.first >= 0) {
        t.keys(tmux_session::mouse_motion(hover.first, hover.second));
        // The pointer's mark shows where it aims.
        REQUIRE(t.wait_for([&](const std::string& s) {
            const auto cells = cells_of(s);
            const auto y = static_cast<std::size_t>(hover.second);
            const auto x = static_cast<std::size_t>(hover.first);
            return y < cells.size() && x < cells[y].size() && cells[y][x] == "+";
        }));
    }
    const std::string with = t.screen();
    t.keys("g");
    REQUIRE(t.wait_for_text("Aiming aid off"));
    const std::string without = t.screen();
    t.kill_session();
    return aid_cells(table, with, without);
}

// The shots of a saved record, in order.
std::vector<RecordedAction> shots_of(const std::string& text) {
    std::vector<RecordedAction> out;
    const auto parsed = parse_record(text);
    if (const GameRecord* r = std::get_if<GameRecord>(&parsed))
        for (const RecordedAction& a : r->actions)
            if (a.kind == RecordedAction::Kind::shot)
                out.push_back(a);
    return out;
}

// The call the panel shows ("calls the 10 in the top-left corner"), with the screen's lines
// joined: its ball and pocket, {0, 0} when none shows.
std::pair<int, int> shown_call(const std::string& screen) {
    std::string flat;
    for (const char c : screen)
        if (c != ' ' && c != '\n')
            flat += c;
        else if (!flat.empty() && flat.back() != ' ')
            flat += ' ';
    const std::size_t at = flat.find("calls the ");
    if (at == std::string::npos)
        return {0, 0};
    const std::string rest = flat.substr(at + 10);
    const int ball = std::atoi(rest.c_str());
    for (int pocket = 1; pocket <= 6; ++pocket)
        if (rest.find(std::string(" in the ") + tui::pocket_name(pocket)) != std::string::npos)
            return {ball, pocket};
    return {ball, 0};
}

} // namespace

TEST_CASE("the assist levels in tmux: a kick's rebound drawn by guided only, standard's short "
          "object line, pro's path to the first contact",
          "[tui][e2e][assist]") {
    const ScratchDir dir("termpool-assist");
    Tmux t;
    const Scenario kick = find_scenario(kick_spot);
    const Table table = make_table(kick.record.setup);
    const std::pair<int, int> cue = cell_of(table, kick.cue);
    std::map<Assist, std::set<std::pair<int, int>>> kick_aid;
    for (const Assist a : {Assist::guided, Assist::standard, Assist::pro}) {
        const std::string save = dir.path + "/kick-" + assist_name(a) + ".save";
        write_save(kick.record, a, save);
        kick_aid[a] = opening_aid(t, dir, table, save);
    }
    // The rail the cue ball goes to first, as the game computes it.
    const auto replayed = Match::replay(kick.record, kick.record.actions.size());
    REQUIRE(std::holds_alternative<Match>(replayed));
    const Game& g = std::get<Match>(replayed).game();
    const tui::AimState guided = opened(g, kick.cue, g.legal_targets(), Assist::guided);
    const std::pair<int, int> rail = cell_of(table, guided.full_preview.kick_leg.back());
    INFO("cue cell " << cue.first << "," << cue.second << "; rail cell " << rail.first << ","
                     << rail.second);
    // Standard and pro draw the cue ball's way to the rail and stop there; guided goes on past
    // the rail to the ball it meets.
    INFO("guided:" << cells_text(kick_aid[Assist::guided])
                   << "\nstandard:" << cells_text(kick_aid[Assist::standard])
                   << "\npro:" << cells_text(kick_aid[Assist::pro]));
    CHECK(cells_outside(kick_aid[Assist::standard], cue, rail, 1) == 0);
    CHECK(cells_outside(kick_aid[Assist::pro], cue, rail, 1) == 0);
    CHECK(cells_outside(kick_aid[Assist::guided], cue, rail, 1) >= 5);

    // A cut at a ball in plain view, aimed with the pointer at the same cell under each level.
    const Scenario cut = find_scenario(cut_spot);
    const auto replayed_cut = Match::replay(cut.record, cut.record.actions.size());
    REQUIRE(std::holds_alternative<Match>(replayed_cut));
    const Ball* target = ball_of(std::get<Match>(replayed_cut).game(), cut.target);
    REQUIRE(target);
    const std::pair<int, int> ball = cell_of(table, target->position);
    std::map<Assist, std::set<std::pair<int, int>>> cut_aid;
    for (const Assist a : {Assist::guided, Assist::standard, Assist::pro}) {
        const std::string save = dir.path + "/cut-" + assist_name(a) + ".save";
        write_save(cut.record, a, save);
        cut_aid[a] = opening_aid(t, dir, table, save, cut.hover);
    }
    // Three ball diameters in cells, and two for the ghost ball and rounding.
    const tui::Layout l = tui::make_layout(table, width, height);
    const int reach = static_cast<int>(std::ceil(6 * 0.028575 * l.cells_per_metre)) + 2;
    INFO("ball cell " << ball.first << "," << ball.second << ", reach " << reach
                      << "\npro:" << cells_text(cut_aid[Assist::pro])
                      << "\nstandard:" << cells_text(cut_aid[Assist::standard])
                      << "\nguided:" << cells_text(cut_aid[Assist::guided]));
    // Pro: nothing off the cue's line. Standard: the ghost ball and a short stretch of the
    // object ball's line, close to the ball. Guided: the object ball's line runs on.
    CHECK(cut_aid[Assist::pro].empty());
    CHECK_FALSE(cut_aid[Assist::standard].empty());
    CHECK(cells_outside(cut_aid[Assist::standard], ball, ball, reach) == 0);
    CHECK(cells_outside(cut_aid[Assist::guided], ball, ball, reach) >= 5);
}

TEST_CASE("each assist's turns open where the level says: guided at the pot, standard and pro "
          "full on the ball",
          "[tui][e2e][assist]") {
    for (const Assist assist : {Assist::guided, Assist::standard, Assist::pro}) {
        CAPTURE(assist_name(assist));
        const ScratchDir dir("termpool-assist");
        Tmux t;
        t.start(game_command(dir, std::string("--player1 Ann --player2 Bob --seed 4 --assist ") +
                                      assist_name(assist)),
                width, height);
        constexpr int shots = 4;
        for (int shot = 0; shot < shots; ++shot) {
            CAPTURE(shot);
            REQUIRE(t.wait_for(
                [](const std::string& s) {
                    return s.find("[ shoot ]") != std::string::npos ||
                           s.find("place the cue ball") != std::string::npos ||
                           s.find("choose") != std::string::npos ||
                           s.find("rematch") != std::string::npos;
                },
                20));
            const std::string screen = t.screen();
            if (screen.find("rematch") != std::string::npos)
                break;
            if (screen.find("choose") != std::string::npos) {
                t.keys("1");
                REQUIRE(t.wait_for_text("[ shoot ]", 20));
            } else if (screen.find("[ shoot ]") == std::string::npos) {
                t.keys("Enter");
                REQUIRE(t.wait_for_text("[ shoot ]"));
            }
            t.keys("Space");
            t.keys("x");
            REQUIRE(t.wait_for(
                [&](const std::string&) {
                    return shots_of(file_text(dir.save())).size() ==
                           static_cast<std::size_t>(shot + 1);
                },
                20));
        }
        const auto parsed = parse_record(file_text(dir.save()));
        REQUIRE(std::holds_alternative<GameRecord>(parsed));
        const GameRecord& record = std::get<GameRecord>(parsed);
        // The save's header holds the level (standard, the default, as no line).
        CHECK(record.assist == assist);
        CHECK((file_text(dir.save()).find(std::string("\nassist ") + assist_name(assist)) !=
               std::string::npos) == (assist != Assist::standard));
        // Replayed: every shot after the break was played where its turn opened, and the
        // openings differ from guided's where the pot is a cut.
        auto started = Match::start(record, 1);
        Match& m = std::get<Match>(started);
        int judged = 0, full = 0;
        for (const RecordedAction& a : record.actions) {
            if (a.kind == RecordedAction::Kind::shot && !m.game().is_break()) {
                const Game& g = m.game();
                const Ball* cue = ball_of(g, 0);
                REQUIRE(cue);
                const auto opening =
                    tui::rank_openings(g.table(), g.balls(), g.params().ball_radius, cue->position,
                                       g.legal_targets(), assist);
                REQUIRE_FALSE(opening.empty());
                ++judged;
                CHECK(a.strike.angle_deg == Approx(opening[0].aim_deg).margin(1e-9));
                const Ball* ball = ball_of(g, opening[0].ball);
                if (opening[0].line == tui::TargetLine::straight && ball &&
                    std::fabs(tui::aim_from_pointer(cue->position, ball->position) -
                              opening[0].aim_deg) < 1e-5)
                    ++full;
            }
            REQUIRE(m.apply(a) == MatchError::none);
        }
        CHECK(judged >= 2);
        if (assist == Assist::guided)
            CHECK(full < judged); // at the ghost ball of a cut, not the ball's centre
        else
            CHECK(full == judged);
    }
}

TEST_CASE("the call in tmux: a warning before a foul, a kick called with a pocket key, the call "
          "shown is the call saved",
          "[tui][e2e][assist]") {
    const ScratchDir dir("termpool-assist");
    Tmux t;
    const Scenario kick = find_scenario(kick_spot);
    const Table table = make_table(kick.record.setup);
    const std::string save = dir.path + "/kick.save";
    write_save(kick.record, Assist::standard, save);
    t.start(game_command(dir, "--resume " + save), width, height);
    REQUIRE(t.wait_for_text("[ shoot ]"));
    // The opening aim is the kick, said so; its ball is called into the pocket it heads for.
    CHECK(t.wait_for_text("a kick off one rail", 5, "e2e", true));
    CHECK(shown_call(t.screen()).first == kick.target);

    // The pointer over the ball in the way: hitting it first is a foul, said before the shot.
    const auto replayed = Match::replay(kick.record, kick.record.actions.size());
    REQUIRE(std::holds_alternative<Match>(replayed));
    const Ball* blocker = ball_of(std::get<Match>(replayed).game(), kick.blocker);
    REQUIRE(blocker);
    const auto [bx, by] = cell_of(table, blocker->position);
    t.keys(tmux_session::mouse_motion(bx, by));
    const std::string warning = "hitting the " + std::to_string(kick.blocker) + " first is a foul";
    CHECK(t.wait_for([&](const std::string& s) { return s.find("foul") != std::string::npos; }, 5));
    CHECK(t.wait_for_text(warning, 5, "e2e", true));
    CHECK(shown_call(t.screen()).first == 0);

    // Back to the kick ([ and ] go through the openings), a pocket chosen with its key: the
    // panel calls it, and the save holds that call.
    t.keys("]");
    REQUIRE(
        t.wait_for([&](const std::string& s) { return shown_call(s).first == kick.target; }, 5));
    t.keys("4");
    REQUIRE(t.wait_for([&](const std::string& s) { return shown_call(s).second == 4; }, 5));
    const std::pair<int, int> shown = shown_call(t.screen());
    // The resumed game goes on in its own save.
    const std::size_t before = shots_of(file_text(save)).size();
    t.keys("Space");
    t.keys("x");
    REQUIRE(t.wait_for(
        [&](const std::string&) { return shots_of(file_text(save)).size() > before; }, 20));
    const auto shots = shots_of(file_text(save));
    CHECK(shots.back().call.call.ball == shown.first);
    CHECK(shots.back().call.call.pocket == shown.second);
    CHECK(shots.back().call.call.pocket == 4);
}

TEST_CASE("Space on the proposed kick meets the legal ball first", "[tui][e2e][assist][kick]") {
    const ScratchDir dir("termpool-assist");
    Tmux t;
    // A position where the mirror aim in the rail misses the lowest ball: the old proposal.
    const Scenario kick = find_scenario(missed_kick_spot);
    const std::string save = dir.path + "/kick.save";
    write_save(kick.record, Assist::standard, save);
    t.start(game_command(dir, "--resume " + save), width, height);
    REQUIRE(t.wait_for_text("[ shoot ]"));
    REQUIRE(t.wait_for_text("a kick off one rail", 5, "e2e", true));
    const std::size_t before = shots_of(file_text(save)).size();
    t.keys("Space");
    t.keys("x");
    REQUIRE(t.wait_for(
        [&](const std::string&) { return shots_of(file_text(save)).size() > before; }, 20));
    t.kill_session();

    // The shot saved, played on the game it was shot in: the lowest ball met first.
    const auto saved = parse_record(file_text(save));
    REQUIRE(std::holds_alternative<GameRecord>(saved));
    const GameRecord& record = std::get<GameRecord>(saved);
    const auto replayed = Match::replay(record, record.actions.size() - 1);
    REQUIRE(std::holds_alternative<Match>(replayed));
    Game game = std::get<Match>(replayed).game();
    const RecordedAction& shot = record.actions.back();
    REQUIRE(shot.kind == RecordedAction::Kind::shot);
    const Verdict v = game.play(shot.strike, shot.call);
    CHECK(v.first_contact == kick.target);
    CHECK(v.foul != Foul::wrong_ball_first);
    CHECK(v.foul != Foul::no_contact);
}

TEST_CASE("the computer's call shown while it aims is the call it makes", "[tui][e2e][assist]") {
    const ScratchDir dir("termpool-assist");
    Tmux t;
    t.start(game_command(dir, "--watch easy --seed 7"), width, height);
    // The break calls nothing: its roll ends at once.
    REQUIRE(t.wait_for_text("shoots", 30));
    t.keys("x");
    int compared = 0;
    for (int turn = 0; turn < 40 && compared < 2; ++turn) {
        // A computer's aim with a call in the panel; the save holds the shots before it.
        if (!t.wait_for([](const std::string& s) { return shown_call(s).second != 0; }, 30))
            break;
        const std::pair<int, int> shown = shown_call(t.screen());
        const std::size_t before = shots_of(file_text(dir.save())).size();
        // The shot rolls (no call shown then): its end at once.
        REQUIRE(t.wait_for([](const std::string& s) { return shown_call(s).second == 0; }, 30));
        t.keys("x");
        REQUIRE(t.wait_for(
            [&](const std::string&) { return shots_of(file_text(dir.save())).size() > before; },
            30));
        const RecordedAction shot = shots_of(file_text(dir.save()))[before];
        CAPTURE(before, shown.first, shown.second);
        CHECK(shot.call.call.ball == shown.first);
        CHECK(shot.call.call.pocket == shown.second);
        ++compared;
    }
    CHECK(compared >= 2);
}
