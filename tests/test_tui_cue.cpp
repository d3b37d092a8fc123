// The cue's elevation and squirt in the terminal game: the keys that raise, lower and level
// the cue, the strike they give, the elevation beside the spin diagram in every tier and at
// every size, and the aiming aid taken from the simulator (squirt turns it, swerve curves it,
// its ghost ball is where the shot meets the ball).
#include <catch2/catch.hpp>
#include <climits>
#include <cmath>
#include <numbers>
#include <string>
#include <termpool/simulator.hpp>
#include <vector>

#include "tui/aid_path.hpp"
#include "tui/aim_state.hpp"
#include "tui/draw.hpp"
#include "tui/view.hpp"
#include "tui_frames.hpp"
#include <termpool/text_width.hpp>

using namespace termpool;
using namespace termpool::tui;
using termpool::test::rack_view;

namespace {

const Table table = make_table(TableSize::nine_foot);
const PhysicsParams params;

Ball ball_at(int id, double x, double y) {
    Ball b;
    b.id = id;
    b.position = {x, y};
    return b;
}

// The glyphs of row y.
std::string row_text(const Grid& g, int y) {
    std::string s;
    for (int x = 0; x < g.width; ++x)
        s += g.at(x, y).glyph;
    return s;
}

// The first cell of `text` in rows y0..y1 and columns x0..x1 (exclusive), or {-1, -1}.
std::pair<int, int> find_in(const Grid& g, const std::string& text, int x0, int y0, int x1,
                            int y1) {
    for (int y = std::max(0, y0); y < std::min(y1, g.height); ++y)
        for (int x = std::max(0, x0); x < std::min(x1, g.width); ++x) {
            std::string s;
            for (int k = x; k < std::min(x1, g.width) && s.size() < text.size(); ++k)
                s += g.at(k, y).glyph;
            if (s == text)
                return {x, y};
        }
    return {-1, -1};
}

// The spin face's '+' (red, bold) in the panel, or {-1, -1}.
std::pair<int, int> face_marker(const Grid& g, const Layout& l) {
    for (int y = l.panel_y; y < l.panel_y + l.panel_height; ++y)
        for (int x = l.panel_x; x < l.panel_x + l.panel_width; ++x)
            if (g.at(x, y).glyph == "+" && g.at(x, y).style.fg == Colour::red)
                return {x, y};
    return {-1, -1};
}

// Largest distance of a path's points from the straight line through its ends, m.
double bow(const std::vector<Vec2>& path) {
    const Vec2 a = path.front(), d = normalized(path.back() - a);
    double most = 0;
    for (const Vec2 p : path)
        most = std::max(most, std::fabs(cross(d, p - a)));
    return most;
}

double direction_deg(Vec2 from, Vec2 to) {
    return std::atan2(to.y - from.y, to.x - from.x) * 180 / std::numbers::pi;
}

} // namespace

TEST_CASE("e and E raise and lower the cue 5 degrees within 0..80, v levels it", "[tui][cue]") {
    AimState aim;
    CHECK(aim.elevation_deg == 0);
    CHECK(aim.elevation_key("e"));
    CHECK(aim.elevation_deg == 5);
    CHECK(aim.elevation_key("e"));
    CHECK(aim.elevation_deg == 10);
    CHECK(aim.elevation_key("E"));
    CHECK(aim.elevation_deg == 5);
    for (int i = 0; i < 30; ++i)
        aim.elevation_key("e");
    CHECK(aim.elevation_deg == max_cue_elevation_deg);
    CHECK(aim.elevation_key("v"));
    CHECK(aim.elevation_deg == 0);
    CHECK(aim.elevation_key("E"));
    CHECK(aim.elevation_deg == 0); // never below level
    // The spin keys leave the elevation alone, and the elevation keys the spin.
    aim.elevation_key("e");
    CHECK(aim.spin_key("d"));
    CHECK(aim.spin_key("c"));
    CHECK(aim.elevation_deg == 5);
    CHECK_FALSE(aim.elevation_key("c"));
    CHECK_FALSE(aim.elevation_key("d"));
    CHECK_FALSE(aim.elevation_key("ee"));
    CHECK_FALSE(aim.spin_key("e"));
    CHECK_FALSE(aim.spin_key("v"));
}

TEST_CASE("the strike carries the elevation, and a new turn levels the cue", "[tui][cue]") {
    AimState aim;
    aim.aim_deg = 12.5;
    aim.power = 0.5;
    aim.side = 0.3;
    aim.follow = -0.1;
    for (int i = 0; i < 6; ++i)
        aim.elevation_key("e");
    const Strike s = aim.strike(false, AimState::Clock::now());
    CHECK(s.speed == speed_from_power(0.5, false));
    CHECK(s.angle_deg == 12.5);
    CHECK(s.side == 0.3);
    CHECK(s.follow == -0.1);
    CHECK(s.elevation_deg == 30);
    CHECK(aim.set_strike(true).elevation_deg == 30);
    CHECK(aim.set_strike(true).speed == speed_from_power(0.5, true));
    aim.new_turn();
    CHECK(aim.elevation_deg == 0);
    CHECK(aim.strike(false, AimState::Clock::now()).elevation_deg == 0);
}

TEST_CASE("the elevation reads in degrees: a degree sign in UTF-8, deg in ASCII", "[tui][cue]") {
    CHECK(format_elevation(0, true) == "elev 0\u00B0");
    CHECK(format_elevation(30, true) == "elev 30\u00B0");
    CHECK(format_elevation(30, false) == "elev 30deg");
    CHECK(format_elevation(12.5, false) == "elev 12.5deg");
    CHECK(format_elevation(80, true) == "elev 80\u00B0");
    CHECK(format_elevation(-0.01, false) == "elev 0deg");
    CHECK(format_elevation(NAN, false) == "elev 0deg");
}

TEST_CASE("the spin diagram shows the elevation in colour, mono and ASCII", "[tui][cue]") {
    View v = rack_view(table);
    v.elevation_deg = 30;
    const Capabilities tiers[] = {{256, true}, {8, true}, {0, true}, {256, false}, {0, false}};
    for (const Capabilities caps : tiers)
        for (const auto& [w, h] : {std::pair{80, 24}, {100, 32}, {120, 40}, {200, 60}}) {
            CAPTURE(caps.colours, caps.utf8, w, h);
            const Layout l = make_layout(table, w, h);
            const Grid g = render(v, l, caps, w, h);
            const std::string label = caps.utf8 ? "elev 30\u00B0" : "elev 30deg";
            // On the spin line under the table, after side and follow.
            const std::string spin_line = row_text(g, l.status_y + 1);
            CHECK(spin_line.find("follow -0.2 " + label) != std::string::npos);
            if (!l.panel_below) {
                // Beside the face, under "follow", left-aligned with it.
                const auto face = face_marker(g, l);
                REQUIRE(face.first >= 0);
                const int x0 = l.panel_x, x1 = l.panel_x + l.panel_width;
                const auto at = find_in(g, label, x0, l.panel_y, x1, l.panel_y + l.panel_height);
                const auto follow =
                    find_in(g, "follow -0.2", x0, l.panel_y, x1, l.panel_y + l.panel_height);
                REQUIRE(at.first >= 0);
                REQUIRE(follow.first >= 0);
                CHECK(at.first == follow.first);
                CHECK(at.second == follow.second + 1);
                CHECK(at.first > face.first);
                // Plain text: the face's colours are not on it.
                CHECK(g.at(at.first, at.second).style.bg == Colour::normal);
            }
        }
}

TEST_CASE("the elevation shows at every size, and the panel keeps its hint", "[tui][cue]") {
    View v = rack_view(table);
    v.elevation_deg = 80;
    v.side = -0.25;
    v.follow = -0.25;
    // A long message takes the side panel's rows: the small face and its four lines still fit.
    const std::string messages[] = {"", v.message + " " + v.message + " " + v.message};
    for (const std::string& message : messages)
        for (int w = 40; w <= 220; w += 3)
            for (int h = 14; h <= 70; h += 4) {
                v.message = message;
                const Layout l = make_layout(table, w, h);
                if (!l.fits)
                    continue;
                CAPTURE(w, h, message.size());
                for (const bool utf8 : {true, false}) {
                    const Grid g = render(v, l, {256, utf8}, w, h);
                    const std::string label = utf8 ? "elev 80\u00B0" : "elev 80deg";
                    CHECK(row_text(g, l.status_y + 1).find(label) != std::string::npos);
                    const int x1 = l.panel_x + l.panel_width, y1 = l.panel_y + l.panel_height;
                    CHECK(find_in(g, "? help", l.panel_x, l.panel_y, x1, y1).first >= 0);
                    if (!l.panel_below && face_marker(g, l).first >= 0)
                        CHECK(find_in(g, label, l.panel_x, l.panel_y, x1, y1).first >= 0);
                }
            }
}

TEST_CASE("the aid follows squirt: side spin turns the cue ball's line away from the side struck",
          "[tui][cue]") {
    const std::vector<Ball> balls = {ball_at(0, 0.4, 0.635)};
    const double squirt = squirt_angle_deg(0.5, params.cue_mass(), params.cue_end_mass);
    REQUIRE(squirt > 1.0);
    for (const double side : {0.5, 0.0, -0.5}) {
        CAPTURE(side);
        const AimPreview p = preview_strike(table, params, balls, {2.0, 0.0, side, 0.0});
        REQUIRE(p.cue_path.size() >= 2);
        CHECK(p.cue_path.front() == balls[0].position);
        // Level: no swerve, a straight line at the squirt angle to the far rail.
        CHECK(bow(p.cue_path) < 1e-9);
        CHECK(direction_deg(p.cue_path.front(), p.cue_path.back()) == Approx(side > 0   ? squirt
                                                                             : side < 0 ? -squirt
                                                                                        : 0.0)
                                                                          .margin(1e-9));
        CHECK(p.cushion >= 0);
    }
    // With no end mass behind the tip the line is the cue's.
    PhysicsParams no_squirt = params;
    no_squirt.cue_end_mass = 0;
    const AimPreview p = preview_strike(table, no_squirt, balls, {2.0, 0.0, 0.5, 0.0});
    CHECK(direction_deg(p.cue_path.front(), p.cue_path.back()) == Approx(0).margin(1e-9));
}

TEST_CASE("the aid's ghost ball is where the simulated shot meets the ball", "[tui][cue]") {
    const std::vector<Ball> balls = {ball_at(0, 0.5, 0.6), ball_at(3, 1.1, 0.6)};
    for (const Strike s : {Strike{2.0, 0.0, 0.5, 0.0, 0.0}, Strike{2.0, 0.0, -0.4, 0.2, 0.0},
                           Strike{2.0, 0.0, 0.5, 0.0, 30.0}}) {
        CAPTURE(s.side, s.follow, s.elevation_deg);
        REQUIRE_FALSE(strike_problem(s, params));
        const AimPreview p = preview_strike(table, params, balls, s);
        Trajectory motion(params, balls.size());
        const ShotResult shot = simulate_shot(table, params, balls, s, &motion);
        const Event* first = nullptr;
        for (const Event& e : shot.events)
            if (e.kind == EventKind::ball_ball) {
                first = &e;
                break;
            }
        REQUIRE(first);
        REQUIRE(p.has_ghost);
        CHECK(p.object_ball == 3);
        CHECK(first->other == 3);
        // The same simulation, sampled the same way: the same point, bit for bit.
        CHECK(p.ghost == motion.sample(first->time)[0].position);
        CHECK(p.cue_path.back() == p.ghost);
        // Not the straight line's ghost: squirt moved it across the object ball.
        const AimPreview straight =
            preview_shot(table, balls, params.ball_radius, balls[0].position, s.angle_deg);
        CHECK(length(straight.ghost - p.ghost) > 0.002);
        // The object ball leaves along the line of centres at contact.
        REQUIRE(p.object_path.size() == 2);
        CHECK(direction_deg(p.object_path[0], p.object_path[1]) ==
              Approx(direction_deg(p.ghost, balls[1].position)).margin(1e-9));
    }
}

TEST_CASE("a raised cue with side spin curves the aid's path as the shot curves", "[tui][cue]") {
    const std::vector<Ball> balls = {ball_at(0, 0.4, 0.635)};
    const Strike level{1.5, 0.0, 0.5, 0.0, 0.0}, raised{1.5, 0.0, 0.5, 0.0, 30.0};
    REQUIRE_FALSE(strike_problem(raised, params));
    const AimPreview flat = preview_strike(table, params, balls, level);
    const AimPreview curved = preview_strike(table, params, balls, raised);
    CHECK(bow(flat.cue_path) < 1e-9);
    CHECK(bow(curved.cue_path) > 0.005);
    // Every point of the path is on the shot's own trajectory, which ends the path at its first
    // contact.
    Trajectory motion(params, balls.size());
    const ShotResult shot = simulate_shot(table, params, balls, raised, &motion);
    REQUIRE_FALSE(shot.events.empty());
    double contact_time = -1;
    for (const Event& e : shot.events)
        if (e.kind == EventKind::cushion || e.kind == EventKind::jaw ||
            e.kind == EventKind::pocket) {
            contact_time = e.time;
            break;
        }
    REQUIRE(contact_time > 0);
    CHECK(curved.cue_path.back() == motion.sample(contact_time)[0].position);
    for (const Vec2 p : curved.cue_path) {
        double nearest = INFINITY;
        for (int k = 0; k <= 4000; ++k)
            nearest =
                std::min(nearest, length(motion.sample(contact_time * k / 4000)[0].position - p));
        CHECK(nearest < 0.002);
    }
}

TEST_CASE("the aid of a strike that cannot be played is the cue's straight line", "[tui][cue]") {
    const std::vector<Ball> balls = {ball_at(0, 0.5, 0.6), ball_at(3, 1.1, 0.6)};
    const Strike jump{7.0, 0.0, 0.0, 0.0, 60.0};
    REQUIRE(strike_problem(jump, params));
    const AimPreview p = preview_strike(table, params, balls, jump);
    const AimPreview straight =
        preview_shot(table, balls, params.ball_radius, balls[0].position, 0.0);
    CHECK(p.cue_path == straight.cue_path);
    CHECK(p.ghost == straight.ghost);
    CHECK(p.object_ball == 3);
    // No cue ball: nothing to draw.
    CHECK(preview_strike(table, params, {balls[1]}, {2.0}).cue_path.empty());
}

TEST_CASE("the drawn aid turns with squirt: right english sends the line up the screen",
          "[tui][cue]") {
    View v;
    v.table = &table;
    v.balls = {ball_at(0, 0.4, 0.635)};
    v.aiming = true;
    v.show_aid = true;
    v.aim_deg = 0;
    const Layout l = make_layout(table, 200, 60);
    // The row of the aid's far end: the rightmost cell drawn in the aim's colour.
    const auto far_end_row = [&](double side) {
        View s = v;
        s.side = side;
        s.cue_path = preview_strike(table, params, s.balls, {2.0, 0.0, side, 0.0}).cue_path;
        const Grid g = render(s, l, {256, true}, 200, 60);
        int best_x = -1, row = -1;
        for (int y = 0; y < g.height; ++y)
            for (int x = 0; x < g.width; ++x)
                if (g.at(x, y).style.fg == Colour::aim && g.at(x, y).style.bg == Colour::felt &&
                    x > best_x)
                    best_x = x, row = y;
        return row;
    };
    const int centre = far_end_row(0), right = far_end_row(0.5), left = far_end_row(-0.5);
    REQUIRE(centre >= 0);
    CHECK(right < centre - 2); // squirt to the left of the cue: up, seen from the head
    CHECK(left > centre + 2);
}

TEST_CASE("the aid ends where a soft shot stops, and starts at once at a frozen ball",
          "[tui][cue]") {
    // Too soft to reach the far rail: the path ends where the simulated ball comes to rest.
    const std::vector<Ball> alone = {ball_at(0, 0.4, 0.635)};
    const Strike soft{0.3, 0.0, 0.2, 0.0, 0.0};
    const AimPreview short_of = preview_strike(table, params, alone, soft);
    const ShotResult rest = simulate_shot(table, params, alone, soft);
    REQUIRE(short_of.cue_path.size() >= 2);
    CHECK(short_of.cue_path.back() == rest.balls[0].position);
    CHECK_FALSE(short_of.has_ghost);
    CHECK(short_of.cushion == -1);
    // A cue ball touching the object ball: the contact is at once, where the cue ball lies.
    const double R = params.ball_radius;
    const std::vector<Ball> frozen = {ball_at(0, 1.0, 0.6), ball_at(5, 1.0 + 2 * R, 0.6)};
    const AimPreview at_once = preview_strike(table, params, frozen, {1.0, 10.0});
    REQUIRE(at_once.has_ghost);
    CHECK(at_once.object_ball == 5);
    CHECK(length(at_once.ghost - frozen[0].position) < 1e-9);
    REQUIRE(at_once.object_path.size() == 2);
    CHECK(direction_deg(at_once.object_path[0], at_once.object_path[1]) == Approx(0).margin(1e-6));
    // Aimed 10 degrees above the line of centres: the cue ball leaves along the tangent, upwards.
    REQUIRE(at_once.deflect_path.size() == 2);
    CHECK(at_once.deflect_path[1].y > at_once.deflect_path[0].y);
}

TEST_CASE("a strike that would jump marks the elevation before Space is pressed", "[tui][cue]") {
    View v = rack_view(table);
    v.elevation_deg = 60;
    for (const Capabilities caps : {Capabilities{256, true}, {0, true}, {0, false}})
        for (const auto& [w, h] : {std::pair{100, 32}, {200, 60}})
            for (const bool refused : {false, true}) {
                CAPTURE(caps.colours, caps.utf8, w, h, refused);
                v.strike_refused = refused;
                const Layout l = make_layout(table, w, h);
                const Grid g = render(v, l, caps, w, h);
                const std::string label = caps.utf8 ? "elev 60\u00B0" : "elev 60deg";
                std::vector<std::pair<int, int>> found;
                for (int y = 0; y < h; ++y) {
                    const auto at = find_in(g, label, 0, y, w, y + 1);
                    if (at.first >= 0)
                        found.push_back(at);
                }
                REQUIRE(found.size() == (l.panel_below ? 1u : 2u));
                for (const auto& [x, y] : found)
                    for (int k = 0; k < display_width(label) && x + k < w; ++k) {
                        const Style s = g.at(x + k, y).style;
                        CHECK(s.bold == refused);
                        if (caps.colours > 0)
                            CHECK((s.fg == Colour::highlight) == refused);
                        else
                            CHECK(s.reverse == refused);
                    }
                // The rest of the spin line stays plain.
                CHECK_FALSE(g.at(l.status_x, l.status_y + 1).style.bold);
            }
}
