// The assist levels and the call: where a turn's aim opens under guided, standard and pro, what
// the aid draws under each, and the call the panel shows being the call the shot makes.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <termpool/record.hpp>
#include <variant>

#include "physics_helpers.hpp"
#include "player/config.hpp"
#include "player/options.hpp"
#include "tui/aid_path.hpp"
#include "tui/aim.hpp"
#include "tui/aim_state.hpp"
#include "tui/shot_call.hpp"
#include "tui_frames.hpp"

using namespace termpool;
using namespace termpool::tui;
using termpool::test::ball_at;

namespace {

const Table table = make_table(TableSize::nine_foot);
const PhysicsParams params;
const double R = params.ball_radius;

// The 3 at a cut of about 35 degrees into the top-right corner (pocket 4); nothing in the way.
const Vec2 cut_cue{1.5, 0.65};
const std::vector<Ball> cut_balls{ball_at(0, cut_cue.x, cut_cue.y), ball_at(3, 1.9, 0.7)};

// Ball 1 hidden behind ball 2 from a cue ball near the bottom-left: only a kick reaches it.
const Vec2 hidden_cue{0.6, 0.6};
const std::vector<Ball> hidden_balls{ball_at(0, 0.6, 0.6), ball_at(1, 1.2, 0.6),
                                     ball_at(2, 0.7, 0.6)};

double path_length(const std::vector<Vec2>& path) {
    double total = 0;
    for (std::size_t i = 1; i < path.size(); ++i)
        total += length(path[i] - path[i - 1]);
    return total;
}

// The aim state of a turn opened under `assist` on `balls`, as the App opens it.
AimState opened(const std::vector<Ball>& balls, Vec2 cue, const std::vector<int>& legal,
                Assist assist, bool calls = true) {
    AimState aim;
    aim.assist = assist;
    aim.new_turn();
    aim.aim_at_target(rank_openings(table, balls, R, cue, legal, assist));
    aim.update_preview(table, params, balls, false, [&](int) { return calls; });
    return aim;
}

} // namespace

TEST_CASE("guided opens at the easiest pot's ghost ball, standard and pro full on the ball",
          "[tui][assist]") {
    const auto ranked = rank_targets(table, cut_balls, R, cut_cue, {3});
    REQUIRE(ranked.size() == 1);
    REQUIRE(ranked[0].pocket == 4);
    const Vec2 ball = cut_balls[1].position;
    const Vec2 pocket = table.pockets[static_cast<std::size_t>(ranked[0].pocket - 1)].position;
    const Vec2 ghost = ball - normalized(pocket - ball) * (2 * R);

    const auto guided = rank_openings(table, cut_balls, R, cut_cue, {3}, Assist::guided);
    const auto standard = rank_openings(table, cut_balls, R, cut_cue, {3}, Assist::standard);
    const auto pro = rank_openings(table, cut_balls, R, cut_cue, {3}, Assist::pro);
    REQUIRE(guided.size() == 1);
    REQUIRE(standard.size() == 1);
    REQUIRE(pro.size() == 1);
    CHECK(guided[0].aim_deg == Approx(aim_from_pointer(cut_cue, ghost)).margin(1e-9));
    CHECK(standard[0].aim_deg == Approx(aim_from_pointer(cut_cue, ball)).margin(1e-9));
    CHECK(pro[0].aim_deg == Approx(standard[0].aim_deg).margin(1e-12));
    // A cut: the two openings are clearly apart.
    CHECK(std::fabs(guided[0].aim_deg - standard[0].aim_deg) > 2);
    // The same ball is proposed: only the aim at it differs.
    CHECK(standard[0].ball == guided[0].ball);

    // Opened under standard, the shot meets the 3 full: the ghost ball on the line of centres.
    const AimState aim = opened(cut_balls, cut_cue, {3}, Assist::standard);
    REQUIRE(aim.preview_ball == 3);
    CHECK(length(aim.preview.ghost - (ball - normalized(ball - cut_cue) * (2 * R))) < 1e-3);

    // A hidden ball is kicked at the same under every assist.
    const auto kick_guided = rank_openings(table, hidden_balls, R, hidden_cue, {1}, Assist::guided);
    const auto kick_standard =
        rank_openings(table, hidden_balls, R, hidden_cue, {1}, Assist::standard);
    REQUIRE(kick_guided.size() == 1);
    REQUIRE(kick_standard.size() == 1);
    CHECK(kick_guided[0].line == TargetLine::kick);
    CHECK(kick_standard[0].aim_deg == kick_guided[0].aim_deg);
}

TEST_CASE("the aid per assist: guided to the rails, standard short, pro to the first contact",
          "[tui][assist]") {
    const Strike strike{2.0, aim_from_pointer(cut_cue, cut_balls[1].position) + 1.5};
    const AimPreview full = preview_strike(table, params, cut_balls, strike, 10, 1);
    REQUIRE(full.object_ball == 3);
    REQUIRE(full.has_ghost);

    // Guided: all of it; the object ball's line goes on past 0.6 m to its rail or pocket.
    const AimPreview guided = shown_preview(full, Assist::guided, R);
    CHECK(guided.object_path == full.object_path);
    CHECK(guided.deflect_path == full.deflect_path);
    CHECK(path_length(guided.object_path) > 0.6);
    CHECK_FALSE(guided.deflect_path.empty());

    // Standard: the cue ball's path, the ghost ball, three diameters of the object ball's line.
    const AimPreview standard = shown_preview(full, Assist::standard, R);
    CHECK(standard.cue_path == full.cue_path);
    CHECK(standard.has_ghost);
    CHECK(path_length(standard.object_path) == Approx(6 * R));
    CHECK(standard.deflect_path.empty());

    // Pro: the cue ball's path to the contact and nothing after it.
    const AimPreview pro = shown_preview(full, Assist::pro, R);
    CHECK(pro.cue_path == full.cue_path);
    CHECK_FALSE(pro.has_ghost);
    CHECK(pro.object_path.empty());
    CHECK(pro.deflect_path.empty());
}

TEST_CASE("a kick: guided draws the rebound to the ball, standard and pro stop at the rail",
          "[tui][assist]") {
    const auto kick = rank_openings(table, hidden_balls, R, hidden_cue, {1}, Assist::guided);
    REQUIRE(kick.size() == 1);
    REQUIRE(kick[0].line == TargetLine::kick);
    const AimState guided = opened(hidden_balls, hidden_cue, {1}, Assist::guided);
    const AimPreview& full = guided.full_preview;
    REQUIRE(full.cushion >= 0);
    REQUIRE(full.kick_leg.size() >= 2);
    // The rebound is drawn: the path goes on past the rail, and the shot's ball is found.
    CHECK(path_length(full.cue_path) > path_length(full.kick_leg) + 0.1);
    CHECK(guided.preview.cue_path == full.cue_path);
    CHECK(guided.preview_ball > 0);
    const Vec2 rail = full.kick_leg.back();
    const CushionSegment& c = table.cushions[static_cast<std::size_t>(full.cushion)];
    CHECK(std::fabs(dot(rail - c.start, c.normal) - R) < 1e-3); // the cue ball at the rail

    for (const Assist assist : {Assist::standard, Assist::pro}) {
        const AimState aim = opened(hidden_balls, hidden_cue, {1}, assist);
        CHECK(aim.preview.cue_path == aim.full_preview.kick_leg);
        CHECK_FALSE(aim.preview.has_ghost);
        CHECK(aim.preview.object_path.empty());
        // The call still reads the ball beyond the rail.
        CHECK(aim.preview_ball == guided.preview_ball);
    }
}

TEST_CASE("a kick or a bank is called with the pocket keys", "[tui][assist][call]") {
    AimState aim = opened(hidden_balls, hidden_cue, {1}, Assist::standard);
    REQUIRE(aim.full_preview.cushion >= 0);
    const int ball = aim.preview_ball;
    REQUIRE(ball == 1);
    // A pocket is proposed for the ball the kick meets, and the keys choose another.
    CHECK(aim.called_pocket != 0);
    aim.called_pocket = 4;
    aim.pocket_chosen = true;
    aim.update_preview(table, params, hidden_balls, false, [](int) { return true; });
    const CallShown call = shot_call(aim, {1}, [](int) { return true; });
    CHECK(call.call.call.ball == ball);
    CHECK(call.call.call.pocket == 4);
    CHECK(call.foul_ball == 0);
}

TEST_CASE("the call: a foul warned of, a combination read as one, a nomination narrows",
          "[tui][assist][call]") {
    AimState aim;
    aim.preview_ball = 4;
    aim.called_pocket = 3;
    const auto calls = [](int) { return true; };
    // On the 8, with the 4 met first: a foul, and the 4 is not called.
    CallShown c = shot_call(aim, {8}, calls);
    CHECK(c.foul_ball == 4);
    CHECK(c.call.call.ball == 0);
    // The 4 legal: it is called into the pocket.
    c = shot_call(aim, {1, 2, 3, 4}, calls);
    CHECK(c.foul_ball == 0);
    CHECK(c.call.call.ball == 4);
    CHECK(c.call.call.pocket == 3);
    // No call in a game that calls none, a safety when one is called.
    CHECK(shot_call(aim, {4}, [](int) { return false; }).call.call.ball == 0);
    aim.safety = true;
    CHECK(shot_call(aim, {4}, calls).call.call.safety);
    aim.safety = false;

    // The computer's call is shown as made: the 10 in pocket 6 off the 5 it hits first.
    aim.preview_ball = 5;
    aim.given_call = ShotCall{{10, 6, false}, false};
    c = shot_call(aim, {5}, calls);
    CHECK(c.call.call.ball == 10);
    CHECK(c.call.call.pocket == 6);
    CHECK(c.off_ball == 5);
    aim.new_turn();
    CHECK_FALSE(aim.given_call);

    // Snooker: a nominated colour is the only ball that may be hit first.
    AimState snooker;
    snooker.preview_ball = 20; // the pink
    snooker.nominated = 21;    // the black
    snooker.nomination_chosen = true;
    CHECK(shot_call(snooker, {16, 17, 18, 19, 20, 21}, [](int) { return false; }).foul_ball == 20);
    snooker.preview_ball = 21;
    CHECK(shot_call(snooker, {16, 17, 18, 19, 20, 21}, [](int) { return false; }).foul_ball == 0);
}

TEST_CASE("the assist is set by --assist and the config, kept in the save's header",
          "[assist][record]") {
    std::string error;
    CHECK(parse_game_options({}, error)->assist == Assist::standard);
    CHECK(parse_game_options({"--assist", "guided"}, error)->assist == Assist::guided);
    CHECK(parse_game_options({"--assist", "pro"}, error)->assist == Assist::pro);
    CHECK_FALSE(parse_game_options({"--assist", "easy"}, error));
    CHECK(error == "unknown assist 'easy' (guided, standard or pro)");
    CHECK_FALSE(parse_game_options({"--assist"}, error));

    GameOptions o;
    std::vector<std::string> warnings;
    CHECK_FALSE(apply_config("assist = pro\n", o, warnings));
    CHECK(o.assist == Assist::pro);
    CHECK(apply_config("\nassist = lots\n", o, warnings) ==
          "2: assist is guided, standard or pro, not 'lots'");

    // Written only when not standard, as version 5; read back; a record without it is standard.
    GameRecord r;
    CHECK(format_record(r).find("assist") == std::string::npos);
    CHECK(format_record(r).starts_with("termpool-record 1\n"));
    r.assist = Assist::guided;
    const std::string text = format_record(r);
    CHECK(text.starts_with("termpool-record 5\n"));
    CHECK(text.find("\nassist guided\n") != std::string::npos);
    const auto back = parse_record(text);
    REQUIRE(std::holds_alternative<GameRecord>(back));
    CHECK(std::get<GameRecord>(back).assist == Assist::guided);
    const auto old = parse_record("termpool-record 4\ngame 8ball\nseed 3\nend\n");
    REQUIRE(std::holds_alternative<GameRecord>(old));
    CHECK(std::get<GameRecord>(old).assist == Assist::standard);

    // A bad value or a line an older version cannot hold: the line and why.
    const auto bad = parse_record("termpool-record 5\ngame 8ball\nassist lots\nend\n");
    REQUIRE(std::holds_alternative<RecordError>(bad));
    CHECK(std::get<RecordError>(bad).line == 3);
    CHECK(std::get<RecordError>(bad).message == "unknown assist 'lots' (guided, standard or pro)");
    const auto early = parse_record("termpool-record 4\ngame 8ball\nassist pro\nend\n");
    REQUIRE(std::holds_alternative<RecordError>(early));
    CHECK(std::get<RecordError>(early).line == 3);
    CHECK(std::get<RecordError>(early).message == "'assist' lines need record version 5");
    // Two assist lines: the second is an error, not a silent winner.
    const auto twice =
        parse_record("termpool-record 5\ngame 8ball\nassist pro\nassist guided\nend\n");
    REQUIRE(std::holds_alternative<RecordError>(twice));
    CHECK(std::get<RecordError>(twice).line == 4);
    CHECK(std::get<RecordError>(twice).message == "a second 'assist' line");
}

namespace {

std::string screen_text(const Grid& g) {
    std::string s;
    for (int y = 0; y < g.height; ++y) {
        for (int x = 0; x < g.width; ++x)
            s += g.at(x, y).glyph;
        s += "\n";
    }
    return s;
}

// The text with each run of blanks and line ends as one space: a line the panel wraps reads
// as one.
std::string joined(const std::string& text) {
    std::string out;
    for (const char c : text)
        if (c != ' ' && c != '\n')
            out += c;
        else if (!out.empty() && out.back() != ' ')
            out += ' ';
    return out;
}

// True when some cell shows `glyph` in the dim role.
bool shown_dim(const Grid& g, const std::string& glyph) {
    for (const Cell& c : g.cells)
        if (c.glyph == glyph && c.style.fg == Colour::dim)
            return true;
    return false;
}

} // namespace

TEST_CASE("the panel reads the call as made: a combination as one call, a foul before it",
          "[tui][assist][call]") {
    View v = termpool::test::rack_view(table);
    const int w = 100, h = 32;
    const Layout l = make_layout(table, w, h);
    v.called_pocket = 6;
    v.called_ball = 10;
    v.call_off_ball = 5;
    std::string text = screen_text(render(v, l, {256, true}, w, h));
    INFO(text);
    CHECK(joined(text).find("calls the 10 in the top-left corner, off the 5") != std::string::npos);
    v.call_off_ball = 0;
    text = screen_text(render(v, l, {256, true}, w, h));
    CHECK(joined(text).find("calls the 10 in the top-left corner ") != std::string::npos);
    CHECK(text.find("off the") == std::string::npos);
    // A ball that may not be hit first: said before the shot, in red, instead of a call.
    v.foul_ball = 4;
    const Grid warned = render(v, l, {256, true}, w, h);
    text = screen_text(warned);
    CHECK(joined(text).find("hitting the 4 first is a foul") != std::string::npos);
    CHECK(text.find("calls the") == std::string::npos);
    const std::size_t at = text.find("hitting the 4");
    const int y = static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
    const std::size_t line_start = text.rfind('\n', at) + 1;
    CHECK(warned.at(static_cast<int>(at - line_start), y).style.fg == Colour::red);
    v.foul_ball = 0;
    v.called_pocket = 0;
    v.called_safety = true;
    CHECK(screen_text(render(v, l, {256, true}, w, h)).find("calls a safety") != std::string::npos);
}

TEST_CASE("guided dims the balls the shooter may not hit first", "[tui][assist]") {
    View v = termpool::test::rack_view(table);
    const Layout l = make_layout(table, 100, 32);
    CHECK_FALSE(shown_dim(render(v, l, {256, true}, 100, 32), "8"));
    v.dimmed_balls = {8};
    CHECK(shown_dim(render(v, l, {256, true}, 100, 32), "8"));
}
