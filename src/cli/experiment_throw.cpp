#include "cli/experiment_throw.hpp"

#include "support/portable_math.hpp"
#include <clocale>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <langinfo.h>
#include <numbers>
#include <string>
#include <termpool/simulator.hpp>
#include <termpool/table.hpp>
#include <vector>

#include "cli/chart.hpp"
#include "cli/numbers.hpp"

namespace termpool::cli {
namespace {

constexpr double degrees = 180 / std::numbers::pi;
constexpr double speeds[] = {0.3, 0.9, 2.0, 5.0}; // m/s at impact
constexpr char speed_marks[] = {'a', 'b', 'c', 'd'};
constexpr int table_step_deg = 5; // the table's rows; the chart takes every degree
constexpr int max_cut_deg = 60;
// The cue ball starts this far short of the contact, so it arrives in the state it was struck
// in: the cloth changes its speed and spin by parts in 10^8 on the way.
constexpr double approach_gap = 1e-6; // m

bool utf8_terminal() {
    std::setlocale(LC_ALL, "");
    const char* codeset = nl_langinfo(CODESET);
    return codeset && std::strcmp(codeset, "UTF-8") == 0;
}

} // namespace

double measured_throw_deg(const PhysicsParams& params, double speed, double cut_deg, bool rolling) {
    const Table table = make_table(TableSize::nine_foot, params.ball_radius);
    const double R = params.ball_radius;
    const double cut = cut_deg / degrees;
    Ball cue, object;
    cue.id = 0;
    cue.mass = params.ball_mass;
    cue.position = {1.0, table.width / 2};
    object.id = 1;
    object.mass = params.ball_mass;
    object.position = {cue.position.x + approach_gap + 2 * R * portable::cos(cut),
                       cue.position.y + 2 * R * portable::sin(cut)};
    World world(table, params, {cue, object});
    // Follow 0.4 of R is natural roll; a centre hit leaves the ball sliding without spin.
    world.strike({speed, 0, 0, rolling ? 0.4 : 0.0});
    while (const auto event = world.step()) {
        if (event->kind != EventKind::ball_ball)
            continue;
        const std::vector<Ball> balls = world.balls();
        const Vec2 centres = balls[1].position - balls[0].position;
        const Vec2 v = balls[1].velocity;
        return (portable::atan2(centres.y, centres.x) - portable::atan2(v.y, v.x)) * degrees;
    }
    return 0; // no contact: a full miss cannot happen here, but it would throw nothing
}

int throw_study(BallFrictionModel model, bool csv) {
    PhysicsParams params;
    params.ball_friction.model = model;
    if (csv)
        std::printf("cue,speed_m_s,cut_deg,throw_deg\n");
    else
        std::printf("Throw: the object ball's departure off the line of centres, degrees, "
                    "ball-ball friction %s\n",
                    name_of(ball_friction_model_names, model));
    const bool utf8 = !csv && utf8_terminal();
    for (const bool rolling : {false, true}) {
        const char* cue = rolling ? "rolling" : "stun";
        std::vector<Series> curves;
        for (std::size_t k = 0; k < std::size(speeds); ++k) {
            Series s{format_number(speeds[k]) + " m/s", speed_marks[k], {}};
            for (int cut = 0; cut <= max_cut_deg; ++cut)
                s.points.emplace_back(cut, measured_throw_deg(params, speeds[k], cut, rolling));
            curves.push_back(std::move(s));
        }
        if (csv) {
            for (std::size_t k = 0; k < std::size(speeds); ++k)
                for (const auto& [cut, angle] : curves[k].points)
                    std::printf("%s,%s,%s,%s\n", cue, format_number(speeds[k]).c_str(),
                                format_number(cut).c_str(), format_number(angle).c_str());
            continue;
        }
        std::printf("\n%s cue ball\n%8s", rolling ? "Rolling" : "Stun", "cut deg");
        for (const double v : speeds)
            std::printf(" %10s", (format_number(v) + " m/s").c_str());
        std::printf("\n");
        for (int cut = 0; cut <= max_cut_deg; cut += table_step_deg) {
            std::printf("%8d", cut);
            for (const Series& s : curves)
                std::printf(" %10.2f", s.points[static_cast<std::size_t>(cut)].second);
            std::printf("\n");
        }
        std::printf("\n%s: throw against cut angle (", cue);
        for (std::size_t k = 0; k < std::size(speeds); ++k) {
            const std::string mark = utf8 ? "" : std::string(1, speed_marks[k]) + " ";
            std::printf("%s%s%s", k ? ", " : "", mark.c_str(), curves[k].name.c_str());
        }
        std::printf("%s)\n", utf8 ? "; the slower, the higher" : "");
        std::fputs(draw_chart(curves, 60, 8, utf8, "deg of cut", "deg of throw").c_str(), stdout);
    }
    if (csv)
        return 0;
    const BallFriction& f = params.ball_friction;
    if (model == BallFrictionModel::fit)
        std::printf("\nu_b = %s + %s e^(-%s v_rel), v_rel the sliding speed of the surfaces at "
                    "impact (m/s).\n",
                    format_number(f.a).c_str(), format_number(f.b).c_str(),
                    format_number(f.c).c_str());
    else
        std::printf("\nu_b = %s at every sliding speed.\n", format_number(f.constant).c_str());
    std::printf("A cut throws tan(throw) = min(u_b, v_rel / (3.5 (1 + e_b) v cos(cut))) "
                "v sin(cut) / v_rel,\nv_rel = v sin(cut) stunned and v rolling: small stun cuts "
                "are limited by the surfaces\nceasing to slide, the rest by u_b.\n");
    return 0;
}

} // namespace termpool::cli
