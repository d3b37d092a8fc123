// The Python module `termpool`: the simulator, the referees and the match, reached from Python
// through the installed interface (include/termpool) only. Names of models, states, fouls and
// choices are the strings the command line and the records use, read and written through the
// core's name tables; errors raise ValueError with the words `termpool simulate` uses.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <termpool/termpool.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "python/arrays.hpp"
#include "python/shots.hpp"

namespace py = pybind11;
using namespace termpool;
using termpool::python::Shot;

namespace {

/// The value `text` names in `table`, or ValueError naming what was expected.
template <class T, std::size_t N>
T parse_or_raise(const NameRow<T> (&table)[N], const std::string& text, const char* what) {
    if (const auto value = parse_name(table, text))
        return *value;
    throw py::value_error("unknown " + std::string(what) + " '" + text + "' (expected " +
                          names_or_list(table) + ")");
}

TableSize table_size_of(const std::string& name) {
    return parse_or_raise(table_size_names, name, "table size");
}

GameType game_type_of(const std::string& name) {
    if (const auto type = parse_game_type(name))
        return *type;
    std::vector<std::string_view> names;
    for (const GameRow& row : game_registry().rows())
        names.push_back(row.name);
    throw py::value_error("unknown game '" + name + "' (expected " + or_list(names) + ")");
}

Level level_of(const std::string& name) {
    return parse_or_raise(level_names, name, "level");
}

/// What a match waits for, in words.
constexpr NameRow<Pending> pending_names[] = {
    {Pending::place, "place"},         {Pending::shoot, "shoot"}, {Pending::choose, "choose"},
    {Pending::next_rack, "next-rack"}, {Pending::over, "over"},
};
static_assert(names_in_order(pending_names));

/// A World with the physics it was made with, against which its strikes are checked.
struct SteppedWorld {
    PhysicsParams physics;
    World world;
};

/// Reads a constant of PhysicsParams that has no scenario name.
template <double PhysicsParams::*field> auto checked_field() {
    return [](const PhysicsParams& p) { return p.*field; };
}

/// Sets it when `value` lies in [low, high] (the low end itself only when `low_allowed`), or
/// raises ValueError as set_physics_parameter words it.
template <double PhysicsParams::*field>
auto checked_setter(const char* name, double low, double high, bool low_allowed) {
    return [=](PhysicsParams& p, double value) {
        const bool above = low_allowed ? value >= low : value > low;
        if (!above || !(value <= high))
            throw py::value_error(std::string(name) + " must be " +
                                  (low_allowed ? "from " : "above ") +
                                  py::repr(py::float_(low)).cast<std::string>() + " to " +
                                  py::repr(py::float_(high)).cast<std::string>() + " (got " +
                                  py::repr(py::float_(value)).cast<std::string>() + ")");
        p.*field = value;
    };
}

/// The physics of `physics`, or the default pool physics.
PhysicsParams physics_or_default(const std::optional<PhysicsParams>& physics) {
    return physics.value_or(PhysicsParams{});
}

/// The table given, or the 9 ft table for the balls of `physics`.
Table table_or_default(const std::optional<Table>& table, const PhysicsParams& physics) {
    return table ? *table : make_table(TableSize::nine_foot, physics.ball_radius);
}

/// A ball as given; without a state, the one its motion implies (sliding when it moves or
/// turns about a horizontal axis, spinning when it only turns about the vertical). The
/// simulator checks the rest (layout_problem) when the ball is used.
Ball make_ball(int id, double x, double y, double vx, double vy, double wx, double wy, double wz,
               std::optional<double> mass, const std::optional<std::string>& state) {
    Ball ball;
    ball.id = id;
    ball.position = {x, y};
    ball.velocity = {vx, vy};
    ball.angular_velocity = {wx, wy, wz};
    if (mass)
        ball.mass = *mass;
    if (state)
        ball.state = parse_or_raise(motion_state_names, *state, "motion state");
    else if (vx != 0 || vy != 0 || wx != 0 || wy != 0)
        ball.state = MotionState::sliding;
    else if (wz != 0)
        ball.state = MotionState::spinning;
    return ball;
}

std::string ball_repr(const Ball& b) {
    return "Ball(id=" + std::to_string(b.id) +
           ", x=" + py::repr(py::float_(b.position.x)).cast<std::string>() +
           ", y=" + py::repr(py::float_(b.position.y)).cast<std::string>() + ", state='" +
           motion_state_name(b.state) + "')";
}

/// Balls' states as columns, one ball after another: what ball_arrays and sample_shot hand
/// over as arrays.
struct BallColumns {
    std::vector<long long> ids, states, pockets;
    std::vector<double> position, velocity, spin;
    void add(const Ball& b) {
        ids.push_back(b.id);
        states.push_back(static_cast<long long>(b.state));
        pockets.push_back(b.pocket);
        position.insert(position.end(), {b.position.x, b.position.y});
        velocity.insert(velocity.end(), {b.velocity.x, b.velocity.y});
        spin.insert(spin.end(), {b.angular_velocity.x, b.angular_velocity.y, b.angular_velocity.z});
    }
    /// The motion as arrays of shape `lead` followed by 2 or 3 (position, velocity,
    /// angular_velocity), and the state codes of shape `lead`, into `out`.
    void put_motion(py::dict& out, const std::vector<std::size_t>& lead) const {
        const auto with = [&](std::size_t last) {
            std::vector<std::size_t> shape = lead;
            shape.push_back(last);
            return shape;
        };
        out["position"] = python::double_array(position, with(2));
        out["velocity"] = python::double_array(velocity, with(2));
        out["angular_velocity"] = python::double_array(spin, with(3));
        out["state"] = python::int_array(states, lead);
    }
};

/// The states of `balls` as arrays: ids (N), position (N, 2), velocity (N, 2), angular
/// velocity (N, 3), state codes (N; MotionState's order) and pocket (N).
py::dict ball_arrays(const std::vector<Ball>& balls) {
    const std::size_t n = balls.size();
    BallColumns columns;
    for (const Ball& b : balls)
        columns.add(b);
    py::dict out;
    out["id"] = python::int_array(columns.ids, {n});
    columns.put_motion(out, {n});
    out["pocket"] = python::int_array(columns.pockets, {n});
    return out;
}

Shot run_shot(const std::vector<Ball>& balls, const Strike& strike,
              const std::optional<Table>& table_given,
              const std::optional<PhysicsParams>& physics_given, bool trajectory) {
    const PhysicsParams physics = physics_or_default(physics_given);
    const Table table = table_or_default(table_given, physics);
    python::check_strike(physics, strike);
    python::check_layout(table, physics, balls);
    Shot shot;
    if (trajectory)
        shot.trajectory.emplace(physics, balls.size());
    {
        py::gil_scoped_release free;
        shot.result = simulate_shot(table, physics, balls, strike,
                                    shot.trajectory ? &*shot.trajectory : nullptr);
    }
    return shot;
}

const Trajectory& trajectory_of(const Shot& shot) {
    if (!shot.trajectory)
        throw py::value_error("this shot was simulated without its trajectory "
                              "(simulate(..., trajectory=True) records it)");
    return *shot.trajectory;
}

/// The states of every ball of the shot at each of `times` (seconds since the strike):
/// arrays of shape (T, N, ...) as ball_arrays gives them, ids (N) once.
py::dict sample_shot(const Shot& shot, const std::vector<double>& times) {
    const Trajectory& trajectory = trajectory_of(shot);
    std::vector<std::size_t> slots;
    for (std::size_t i = 0; i < trajectory.size(); ++i)
        if (!trajectory.pieces(i).empty())
            slots.push_back(i);
    const std::size_t t_count = times.size(), n = slots.size();
    std::vector<long long> ids;
    for (const std::size_t slot : slots)
        ids.push_back(trajectory.pieces(slot).front().ball.id);
    BallColumns columns;
    for (const double t : times) {
        if (!(t >= 0) || !std::isfinite(t))
            throw py::value_error("sample times are seconds since the strike: finite and >= 0");
        for (const std::size_t slot : slots)
            columns.add(trajectory.sample(slot, t));
    }
    py::dict out;
    out["time"] = python::double_array(times, {t_count});
    out["id"] = python::int_array(ids, {n});
    columns.put_motion(out, {t_count, n});
    return out;
}

/// The events as columns: time, kind (EventKind's order), ball, other.
py::dict event_columns(const std::vector<Event>& events) {
    std::vector<double> times;
    std::vector<long long> kinds, balls, others;
    for (const Event& e : events) {
        times.push_back(e.time);
        kinds.push_back(static_cast<long long>(e.kind));
        balls.push_back(e.ball);
        others.push_back(e.other);
    }
    const std::size_t n = events.size();
    py::dict out;
    out["time"] = python::double_array(times, {n});
    out["kind"] = python::int_array(kinds, {n});
    out["ball"] = python::int_array(balls, {n});
    out["other"] = python::int_array(others, {n});
    return out;
}

/// The balls of one layout or of one per strike, from a Python list of Balls or of lists.
std::vector<std::vector<Ball>> layouts_of(const py::object& balls) {
    std::vector<std::vector<Ball>> layouts;
    const py::list list = py::list(balls);
    try {
        if (list.empty() || py::isinstance<Ball>(list[0]))
            layouts.push_back(list.cast<std::vector<Ball>>());
        else
            layouts = list.cast<std::vector<std::vector<Ball>>>();
    } catch (const py::cast_error&) {
        throw py::type_error("balls must be a list of Balls (one layout for every strike) or a "
                             "list of such lists (one per strike)");
    }
    return layouts;
}

std::vector<Shot> simulate_many(const py::object& balls, const std::vector<Strike>& strikes,
                                const std::optional<Table>& table_given,
                                const std::optional<PhysicsParams>& physics_given,
                                unsigned threads) {
    const PhysicsParams physics = physics_or_default(physics_given);
    const Table table = table_or_default(table_given, physics);
    const std::vector<std::vector<Ball>> layouts = layouts_of(balls);
    if (layouts.size() != 1 && layouts.size() != strikes.size())
        throw py::value_error("give one layout of balls, or one per strike (" +
                              std::to_string(strikes.size()) + " strikes, " +
                              std::to_string(layouts.size()) + " layouts)");
    // Each layout and each strike is checked once; an error names the shot it belongs to.
    for (std::size_t i = 0; i < strikes.size(); ++i) {
        try {
            python::check_strike(physics, strikes[i]);
            if (i < layouts.size())
                python::check_layout(table, physics, layouts[i]);
        } catch (const py::value_error& e) {
            throw py::value_error("shot " + std::to_string(i) + ": " + e.what());
        }
    }
    py::gil_scoped_release free;
    return python::simulate_batch(table, physics, layouts, strikes, threads);
}

/// Raises ValueError for a refused match action.
void raise_on(MatchError error) {
    if (error != MatchError::none)
        throw py::value_error(match_error_text(error));
}

ShotCall make_call(int ball, int pocket, bool safety, bool push_out) {
    ShotCall call;
    call.call.ball = ball;
    call.call.pocket = pocket;
    call.call.safety = safety;
    call.push_out = push_out;
    return call;
}

std::vector<std::string> choice_texts(const std::vector<Choice>& choices) {
    std::vector<std::string> out;
    for (const Choice c : choices)
        out.push_back(choice_name(c));
    return out;
}

/// The cloth model a scenario's friction line gives in words ("physical", "decay K", ...),
/// refused in the words simulate uses.
FrictionModel friction_of(const std::string& text) {
    std::vector<std::string> words;
    std::string word;
    for (const char c : text + " ") {
        if (c != ' ') {
            word += c;
        } else if (!word.empty()) {
            words.push_back(word);
            word.clear();
        }
    }
    const std::vector<std::string_view> views(words.begin(), words.end());
    const auto model = parse_friction(views);
    if (const auto* problem = std::get_if<FrictionProblem>(&model))
        throw py::value_error(friction_problem_text(
            *problem, views, "physical | decay K | constant A | combined K A"));
    return std::get<FrictionModel>(model);
}

/// A match made from its settings, as the game's menus and the hall make one.
Match start_match(const std::string& game, const std::optional<std::string>& table,
                  std::pair<std::string, std::string> names,
                  std::pair<std::optional<std::string>, std::optional<std::string>> computers,
                  std::uint64_t seed, int breaker, int race_to, const std::string& friction) {
    GameRecord header;
    header.setup.game = game_type_of(game);
    if (table)
        header.setup.table = table_size_of(*table);
    header.setup.physics.friction = friction_of(friction);
    header.seed = seed;
    if (breaker != 1 && breaker != 2)
        throw py::value_error("breaker must be 1 or 2");
    header.breaker = breaker;
    header.names[0] = names.first;
    header.names[1] = names.second;
    if (computers.first)
        header.computers[0] = level_of(*computers.first);
    if (computers.second)
        header.computers[1] = level_of(*computers.second);
    header.race_to = race_to;
    auto started = Match::start(header, seed);
    if (const auto* error = std::get_if<MatchError>(&started))
        raise_on(*error);
    return std::move(std::get<Match>(started));
}

void bind_physics(py::module_& m) {
    py::class_<Table>(m, "Table", "A table: the playing surface, cushions, jaws and pockets (m).")
        .def(py::init([](const std::string& size, double ball_radius) {
                 if (!(ball_radius > 0) || !std::isfinite(ball_radius))
                     throw py::value_error("ball_radius must be > 0");
                 return make_table(table_size_of(size), ball_radius);
             }),
             py::arg("size") = "9ft", py::arg("ball_radius") = 0.028575)
        .def_static(
            "custom",
            [](double length, double width, double ball_radius) {
                if (!(length > 8 * ball_radius) || !(width > 8 * ball_radius) ||
                    !std::isfinite(length) || !std::isfinite(width) || !(ball_radius > 0))
                    throw py::value_error("a table must be finite and hold at least 8 balls' "
                                          "radii each way");
                return make_table(length, width, ball_radius, PocketSpec{});
            },
            py::arg("length"), py::arg("width"), py::arg("ball_radius") = 0.028575,
            "A table of any size (m) with WPA pockets.")
        .def_property_readonly("size", [](const Table& t) { return table_size_name(t.size); })
        .def_readonly("length", &Table::length)
        .def_readonly("width", &Table::width)
        .def_property_readonly(
            "foot_spot", [](const Table& t) { return std::pair(t.foot_spot().x, t.foot_spot().y); })
        .def_property_readonly(
            "head_spot", [](const Table& t) { return std::pair(t.head_spot().x, t.head_spot().y); })
        .def_property_readonly("pockets",
                               [](const Table& t) {
                                   std::vector<std::pair<double, double>> out;
                                   for (const Pocket& p : t.pockets)
                                       out.emplace_back(p.position.x, p.position.y);
                                   return out;
                               })
        .def(
            "on_table",
            [](const Table& t, double x, double y, double radius) {
                return on_playing_surface(t, {x, y}, radius);
            },
            py::arg("x"), py::arg("y"), py::arg("radius") = 0.028575)
        .def("__repr__", [](const Table& t) {
            return "Table('" + std::string(table_size_name(t.size)) + "', " +
                   py::repr(py::float_(t.length)).cast<std::string>() + " x " +
                   py::repr(py::float_(t.width)).cast<std::string>() + " m)";
        });

    py::class_<PhysicsParams>(m, "Physics",
                              "The simulator's constants and models (SI units). Constants by "
                              "their scenario names: u_s, u_r, u_sp, e_b, u_b, e_c, f_c, w_c, g, "
                              "R, m.")
        .def(py::init([](std::optional<std::string> table) {
                 return table ? physics_for_table(table_size_of(*table)) : PhysicsParams{};
             }),
             py::arg("table") = py::none())
        .def("__getitem__",
             [](const PhysicsParams& p, const std::string& name) {
                 if (const auto value = physics_parameter(p, name))
                     return *value;
                 PhysicsParams scratch = p;
                 throw py::key_error(*set_physics_parameter(scratch, name, 0));
             })
        .def("__setitem__",
             [](PhysicsParams& p, const std::string& name, double value) {
                 if (const auto problem = set_physics_parameter(p, name, value))
                     throw py::value_error(*problem);
             })
        .def_property(
            "collision",
            [](const PhysicsParams& p) { return name_of(collision_model_names, p.collision); },
            [](PhysicsParams& p, const std::string& name) {
                p.collision = parse_or_raise(collision_model_names, name, "collision model");
            })
        .def_property(
            "cushion",
            [](const PhysicsParams& p) { return name_of(cushion_model_names, p.cushion); },
            [](PhysicsParams& p, const std::string& name) {
                p.cushion = parse_or_raise(cushion_model_names, name, "cushion model");
            })
        .def_property(
            "friction", [](const PhysicsParams& p) { return format_friction(p.friction); },
            [](PhysicsParams& p, const std::string& text) { p.friction = friction_of(text); },
            "The cloth model as a scenario's friction line gives it: 'physical', 'decay K', "
            "'constant A' or 'combined K A'.")
        .def_property(
            "throw_fit",
            [](const PhysicsParams& p) {
                return std::tuple(p.ball_friction.a, p.ball_friction.b, p.ball_friction.c);
            },
            [](PhysicsParams& p, std::tuple<double, double, double> abc) {
                const auto [a, b, c] = abc;
                if (!(a >= 0) || !(b >= 0) || !(c >= 0) || !std::isfinite(a + b + c))
                    throw py::value_error("fit constants must be finite and >= 0");
                p.ball_friction = {BallFrictionModel::fit, a, b, c, p.ball_friction.constant};
            },
            "Ball-ball friction u_b = a + b exp(-c v_rel) (setting it selects the fit law).")
        .def_property("cushion_height_ratio", checked_field<&PhysicsParams::cushion_height_ratio>(),
                      checked_setter<&PhysicsParams::cushion_height_ratio>("cushion_height_ratio",
                                                                           0.5, 1, false),
                      "The cushion nose's height as a fraction of 2R (above the centre, 0.5 to "
                      "1).")
        .def_property("cue_end_mass", checked_field<&PhysicsParams::cue_end_mass>(),
                      checked_setter<&PhysicsParams::cue_end_mass>("cue_end_mass", 0, 1, true),
                      "The cue's effective end mass, kg (0: no squirt).")
        .def_property("cue_ball_mass", checked_field<&PhysicsParams::cue_ball_mass>(),
                      checked_setter<&PhysicsParams::cue_ball_mass>("cue_ball_mass", 0, 1, true),
                      "The mass a rack gives the cue ball, kg (0: as the others).")
        .def_property(
            "elastic_below_speed", checked_field<&PhysicsParams::elastic_below_speed>(),
            checked_setter<&PhysicsParams::elastic_below_speed>("elastic_below_speed", 0, 1, true),
            "Below this approach speed (m/s) collisions are elastic.")
        .def("__repr__", [](const PhysicsParams& p) {
            std::string out = "Physics(";
            for (const std::string_view name : physics_parameter_names)
                out += std::string(name) + "=" +
                       py::repr(py::float_(*physics_parameter(p, name))).cast<std::string>() + ", ";
            return out + "collision='" + name_of(collision_model_names, p.collision) +
                   "', cushion='" + name_of(cushion_model_names, p.cushion) + "', friction='" +
                   format_friction(p.friction) + "')";
        });

    py::class_<Ball>(m, "Ball",
                     "One ball: id (0 the cue ball), position and velocity (m, m/s), "
                     "angular velocity (rad/s), mass (kg), motion state.")
        .def(py::init(&make_ball), py::arg("id"), py::arg("x"), py::arg("y"), py::arg("vx") = 0.0,
             py::arg("vy") = 0.0, py::arg("wx") = 0.0, py::arg("wy") = 0.0, py::arg("wz") = 0.0,
             py::arg("mass") = py::none(), py::arg("state") = py::none())
        .def_readwrite("id", &Ball::id)
        .def_property(
            "position", [](const Ball& b) { return std::pair(b.position.x, b.position.y); },
            [](Ball& b, std::pair<double, double> p) {
                b.position = {p.first, p.second};
            })
        .def_property(
            "velocity", [](const Ball& b) { return std::pair(b.velocity.x, b.velocity.y); },
            [](Ball& b, std::pair<double, double> v) {
                b.velocity = {v.first, v.second};
            })
        .def_property(
            "angular_velocity",
            [](const Ball& b) {
                return std::tuple(b.angular_velocity.x, b.angular_velocity.y, b.angular_velocity.z);
            },
            [](Ball& b, std::tuple<double, double, double> w) {
                b.angular_velocity = {std::get<0>(w), std::get<1>(w), std::get<2>(w)};
            })
        .def_readwrite("mass", &Ball::mass)
        .def_property(
            "state", [](const Ball& b) { return motion_state_name(b.state); },
            [](Ball& b, const std::string& s) {
                b.state = parse_or_raise(motion_state_names, s, "motion state");
            })
        .def_readonly("pocket", &Ball::pocket)
        .def("__eq__", [](const Ball& a, const Ball& b) { return a == b; })
        .def("__repr__", &ball_repr);

    py::class_<Strike>(m, "Strike",
                       "A cue strike: speed (m/s), angle (degrees from +x), side and follow "
                       "(tip offsets as fractions of R, at most 0.5), elevation (degrees).")
        .def(py::init([](double speed, double angle, double side, double follow, double elevation) {
                 return Strike{speed, angle, side, follow, elevation};
             }),
             py::arg("speed"), py::arg("angle") = 0.0, py::arg("side") = 0.0,
             py::arg("follow") = 0.0, py::arg("elevation") = 0.0)
        .def_readwrite("speed", &Strike::speed)
        .def_readwrite("angle", &Strike::angle_deg)
        .def_readwrite("side", &Strike::side)
        .def_readwrite("follow", &Strike::follow)
        .def_readwrite("elevation", &Strike::elevation_deg)
        .def("__repr__", [](const Strike& s) {
            return "Strike(speed=" + py::repr(py::float_(s.speed)).cast<std::string>() +
                   ", angle=" + py::repr(py::float_(s.angle_deg)).cast<std::string>() + ")";
        });

    py::class_<Event>(m, "Event",
                      "One event of a shot: time (s), kind, ball, other (a ball, "
                      "rail 0..5 or pocket 1..6, by kind).")
        .def_readonly("time", &Event::time)
        .def_property_readonly("kind", [](const Event& e) { return event_kind_name(e.kind); })
        .def_readonly("ball", &Event::ball)
        .def_readonly("other", &Event::other)
        .def("__repr__", [](const Event& e) {
            return "Event(" + py::repr(py::float_(e.time)).cast<std::string>() + ", '" +
                   event_kind_name(e.kind) + "', " + std::to_string(e.ball) + ", " +
                   std::to_string(e.other) + ")";
        });

    py::class_<EventState>(m, "EventState",
                           "The balls of one event just before it and just after it.")
        .def_readonly("ball_before", &EventState::ball_before)
        .def_readonly("ball_after", &EventState::ball_after)
        .def_readonly("other_before", &EventState::other_before)
        .def_readonly("other_after", &EventState::other_after);

    py::class_<Shot>(m, "Shot",
                     "A simulated shot: its events, the balls at rest, and (when "
                     "recorded) its motion, sampled at any times without "
                     "simulating again.")
        .def_property_readonly("events", [](const Shot& s) { return s.result.events; })
        .def_property_readonly("balls", [](const Shot& s) { return s.result.balls; })
        .def_property_readonly("event_count", [](const Shot& s) { return s.result.events.size(); })
        .def(
            "ball",
            [](const Shot& s, int id) {
                for (const Ball& b : s.result.balls)
                    if (b.id == id)
                        return b;
                throw py::key_error("no ball " + std::to_string(id) + " in this shot");
            },
            py::arg("id"), "The final state of ball `id`.")
        .def_property_readonly("rest_time", [](const Shot& s) { return s.result.rest_time; })
        .def_property_readonly("event_limit_hit",
                               [](const Shot& s) { return s.result.event_limit_hit; })
        .def_property_readonly("has_trajectory",
                               [](const Shot& s) { return s.trajectory.has_value(); })
        .def(
            "event_columns", [](const Shot& s) { return event_columns(s.result.events); },
            "The events as columns (arrays): time, kind (index into EVENT_KINDS), ball, other.")
        .def(
            "final_arrays", [](const Shot& s) { return ball_arrays(s.result.balls); },
            "The balls at rest as arrays: id, position (N,2), velocity, angular_velocity (N,3), "
            "state (index into MOTION_STATES), pocket.")
        .def("sample", &sample_shot, py::arg("times"),
             "Every ball at each time (s): arrays time (T), id (N), position (T,N,2), velocity "
             "(T,N,2), angular_velocity (T,N,3), state (T,N).")
        .def(
            "event_state",
            [](const Shot& s, std::size_t index) {
                if (index >= s.result.events.size())
                    throw py::index_error("event " + std::to_string(index) + " of " +
                                          std::to_string(s.result.events.size()));
                return event_state(trajectory_of(s), s.result.events[index]);
            },
            py::arg("index"), "The states of event `index`'s balls before and after it.");
}

void bind_simulation(py::module_& m) {
    m.def(
        "rack",
        [](const std::string& game, const std::optional<Table>& table_given,
           const std::optional<PhysicsParams>& physics_given, std::optional<std::uint64_t> seed) {
            const RackType type =
                parse_name(rack_type_names, game)
                    ? *parse_name(rack_type_names, game)
                    : game_rack(game_type_of(game)); // Without a table, snooker's rack goes on the
                                                     // snooker table and the others on the 9 ft
            // one, each with its own balls.
            const TableSize size =
                type == RackType::snooker ? TableSize::snooker : TableSize::nine_foot;
            const PhysicsParams physics = physics_given ? *physics_given : physics_for_table(size);
            const Table table = table_given ? *table_given : make_table(size, physics.ball_radius);
            return make_rack(table, physics, type, seed);
        },
        py::arg("game") = "8ball", py::arg("table") = py::none(), py::arg("physics") = py::none(),
        py::arg("seed") = py::none(),
        "The balls of a game's rack (8ball, 9ball, 10ball, snooker), the cue ball on the head "
        "spot (in the D in snooker); a seed shuffles and jitters it as a game does.");

    m.def("simulate", &run_shot, py::arg("balls"), py::arg("strike"), py::arg("table") = py::none(),
          py::arg("physics") = py::none(), py::arg("trajectory") = true,
          "Strikes ball 0 and simulates until every ball is at rest. Without a table, the 9 ft "
          "table; without physics, the defaults. ValueError names what is wrong with the input.");

    m.def("simulate_many", &simulate_many, py::arg("balls"), py::arg("strikes"),
          py::arg("table") = py::none(), py::arg("physics") = py::none(), py::arg("threads") = 0,
          "Simulates every strike, each from `balls` (one layout) or from its own layout (a "
          "list of layouts), across `threads` threads (0: every core), without trajectories. "
          "The results are the same bits as one simulate() each.");

    py::class_<SteppedWorld>(m, "World", "A table with balls, stepped event by event.")
        .def(py::init([](const std::vector<Ball>& balls, const std::optional<Table>& table_given,
                         const std::optional<PhysicsParams>& physics_given) {
                 const PhysicsParams physics = physics_or_default(physics_given);
                 const Table table = table_or_default(table_given, physics);
                 if (const auto problem = python::layout_text(table, physics, balls))
                     throw py::value_error(*problem);
                 return SteppedWorld{physics, World(table, physics, balls)};
             }),
             py::arg("balls"), py::arg("table") = py::none(), py::arg("physics") = py::none())
        .def(
            "strike",
            [](SteppedWorld& w, const Strike& strike) {
                python::check_strike(w.physics, strike);
                if (!w.world.strike(strike))
                    throw py::value_error(no_cue_ball_text);
            },
            py::arg("strike"))
        .def(
            "step", [](SteppedWorld& w) { return w.world.step(); },
            "The next event, resolved; None once every ball is at rest.")
        .def_property_readonly("time", [](const SteppedWorld& w) { return w.world.time(); })
        .def_property_readonly("balls", [](const SteppedWorld& w) { return w.world.balls(); })
        .def_property_readonly("at_rest", [](const SteppedWorld& w) { return w.world.at_rest(); });
}

void bind_rules(py::module_& m) {
    py::class_<Verdict>(m, "Verdict", "What the referee made of a shot.")
        .def_property_readonly("foul", [](const Verdict& v) { return foul_name(v.foul); })
        .def_property_readonly("fouls",
                               [](const Verdict& v) {
                                   std::vector<std::string> out;
                                   for (const Foul f : v.fouls)
                                       out.push_back(foul_name(f));
                                   return out;
                               })
        .def_readonly("first_contact", &Verdict::first_contact)
        .def_readonly("pocketed", &Verdict::pocketed)
        .def_readonly("legal_break", &Verdict::legal_break)
        .def_readonly("next_shooter", &Verdict::next_shooter)
        .def_property_readonly("ball_in_hand",
                               [](const Verdict& v) { return ball_in_hand_name(v.ball_in_hand); })
        .def_readonly("chooser", &Verdict::chooser)
        .def_property_readonly("choices", [](const Verdict& v) { return choice_texts(v.choices); })
        .def_readonly("respotted", &Verdict::respotted)
        .def_readonly("winner", &Verdict::winner)
        .def_property_readonly("reason", [](const Verdict& v) { return win_reason_name(v.reason); })
        .def_readonly("points", &Verdict::points)
        .def_readonly("penalty", &Verdict::penalty)
        .def("__repr__", [](const Verdict& v) {
            return "Verdict(foul='" + std::string(foul_name(v.foul)) +
                   "', next_shooter=" + std::to_string(v.next_shooter) +
                   ", winner=" + std::to_string(v.winner) + ")";
        });

    py::class_<Game>(m, "Game",
                     "One rack between players 1 and 2 with its referee: 8ball, 8ball-bar, "
                     "9ball, 10ball or snooker.")
        .def(py::init([](const std::string& game, const std::optional<std::string>& table,
                         const std::optional<PhysicsParams>& physics, int breaker,
                         std::uint64_t seed) {
                 if (breaker != 1 && breaker != 2)
                     throw py::value_error("breaker must be 1 or 2");
                 GameSetup setup;
                 setup.game = game_type_of(game);
                 if (table)
                     setup.table = table_size_of(*table);
                 if (physics)
                     setup.physics = *physics;
                 Game made = make_game(setup, breaker, seed);
                 if (const auto problem =
                         python::layout_text(made.table(), made.params(), made.balls()))
                     throw py::value_error("the rack does not fit this physics: " + *problem);
                 return made;
             }),
             py::arg("game") = "8ball", py::arg("table") = py::none(),
             py::arg("physics") = py::none(), py::arg("breaker") = 1, py::arg("seed") = 1)
        .def_property_readonly(
            "type",
            [](const Game& g) {
                return game_type_name(g.type());
            }) // Copies: a game's table and physics are not Python's to change under it.
        .def_property_readonly("table", [](const Game& g) { return g.table(); })
        .def_property_readonly("physics", [](const Game& g) { return g.params(); })
        .def_property_readonly("balls", &Game::balls)
        .def_property_readonly("shooter", &Game::shooter)
        .def_property_readonly("is_break", &Game::is_break)
        .def_property_readonly("ball_in_hand",
                               [](const Game& g) { return ball_in_hand_name(g.ball_in_hand()); })
        .def_property_readonly("chooser", &Game::chooser)
        .def_property_readonly("choices", [](const Game& g) { return choice_texts(g.choices()); })
        .def_property_readonly("winner", &Game::winner)
        .def_property_readonly("over", [](const Game& g) { return g.winner() != 0; })
        .def_property_readonly("win_reason",
                               [](const Game& g) { return win_reason_name(g.win_reason()); })
        .def("group_of", [](const Game& g, int player) { return group_name(g.group_of(player)); })
        .def("score_of", &Game::score_of)
        .def("legal_targets", &Game::legal_targets, "Balls the shooter may legally hit first.")
        .def("balls_on", &Game::balls_on)
        .def("pocket_must_be_called", &Game::pocket_must_be_called, py::arg("ball"))
        .def("ready_to_shoot", &Game::ready_to_shoot)
        .def(
            "legal_placement",
            [](const Game& g, double x, double y) {
                return g.legal_placement({x, y});
            },
            py::arg("x"), py::arg("y"))
        .def(
            "legal_placements",
            [](const Game& g, int per_axis) {
                if (per_axis < 1 || per_axis > 1000)
                    throw py::value_error("per_axis must be 1 to 1000");
                std::vector<std::pair<double, double>> out;
                for (const Vec2 p : g.legal_placements(per_axis))
                    out.emplace_back(p.x, p.y);
                return out;
            },
            py::arg("per_axis") = 12)
        .def(
            "place_cue_ball",
            [](Game& g, double x, double y) {
                if (!g.place_cue_ball({x, y}))
                    throw py::value_error("the cue ball may not go there");
            },
            py::arg("x"), py::arg("y"))
        .def(
            "choose",
            [](Game& g, const std::string& choice) {
                if (!g.choose(parse_or_raise(choice_names, choice, "choice")))
                    throw py::value_error("the choice is not among those on offer");
            },
            py::arg("choice"))
        .def(
            "play",
            [](Game& g, const Strike& strike, int ball, int pocket, bool safety, bool push_out) {
                if (const auto problem = strike_problem(strike, g.params()))
                    throw py::value_error(*problem);
                if (!g.ready_to_shoot())
                    throw py::value_error(g.winner() ? "the game is over"
                                                     : "the game waits for a choice or a "
                                                       "placement of the cue ball");
                Shot shot;
                Verdict verdict;
                {
                    // The GIL is kept while this object changes: another thread may be reading it.
                    verdict =
                        g.play(strike, make_call(ball, pocket, safety, push_out), &shot.result);
                }
                return std::pair(verdict, shot);
            },
            py::arg("strike"), py::arg("ball") = 0, py::arg("pocket") = 0,
            py::arg("safety") = false, py::arg("push_out") = false,
            "Simulates the strike from the balls and lets the referee judge it: (Verdict, Shot).")
        .def("copy", [](const Game& g) { return Game(g); });

    py::class_<PlayedShot>(m, "PlayedShot", "A shot played in a match.")
        .def_readonly("shooter", &PlayedShot::shooter)
        .def_readonly("rack", &PlayedShot::rack)
        .def_readonly("was_break", &PlayedShot::was_break)
        .def_readonly("verdict", &PlayedShot::verdict)
        .def_property_readonly("shot", [](const PlayedShot& p) {
            return Shot{p.result, {}};
        });

    py::class_<Match>(m, "Match",
                      "A game or a race between two seats, as every front end plays it: whose "
                      "turn, what is pending, the record; a computer may sit in either seat.")
        .def(py::init(&start_match), py::arg("game") = "8ball", py::arg("table") = py::none(),
             py::arg("names") = std::pair<std::string, std::string>("Player 1", "Player 2"),
             py::arg("computers") =
                 std::pair<std::optional<std::string>, std::optional<std::string>>(),
             py::arg("seed") = 1, py::arg("breaker") = 1, py::arg("race_to") = 1,
             py::arg("friction") = "physical")
        .def_static(
            "replay",
            [](const std::string& text) {
                auto record = parse_record(text);
                if (const auto* error = std::get_if<RecordError>(&record))
                    throw py::value_error("line " + std::to_string(error->line) + ": " +
                                          error->message);
                auto replayed = Match::replay(std::get<GameRecord>(record));
                if (const auto* error = std::get_if<RecordError>(&replayed))
                    throw py::value_error("line " + std::to_string(error->line) + ": " +
                                          error->message);
                return std::move(std::get<Match>(replayed));
            },
            py::arg("text"),
            "The match a record (`record()`, a saved game) plays into, checked as the game "
            "checks it.") // A copy: the match's game moves on only through the match's actions.
        .def_property_readonly("game", [](const Match& match) { return match.game(); })
        .def_property_readonly("rack", &Match::rack)
        .def_property_readonly("state_hash", &Match::state_hash)
        .def(
            "pending",
            [](const Match& match) {
                const PendingAction p = match.pending();
                py::dict out;
                out["kind"] = name_of(pending_names, p.kind);
                out["player"] = p.player;
                out["ball_in_hand"] = ball_in_hand_name(p.ball_in_hand);
                out["choices"] = choice_texts(p.choices);
                return out;
            },
            "What the match waits for: kind (place, shoot, choose, next-rack, over), player, "
            "ball_in_hand, choices.")
        .def_property_readonly("computer_to_act", &Match::computer_to_act)
        .def(
            "place",
            [](Match& match, int player, double x, double y) {
                raise_on(match.place(player, {x, y}));
            },
            py::arg("player"), py::arg("x"), py::arg("y"))
        .def(
            "shoot",
            [](Match& match, int player, const Strike& strike, int ball, int pocket, bool safety,
               bool push_out) {
                if (const auto problem = strike_problem(strike, match.game().params()))
                    throw py::value_error(*problem);
                std::variant<PlayedShot, MatchError> played = MatchError::none;
                {
                    // The GIL is kept while this object changes: another thread may be reading it.
                    played = match.shoot(player, strike, make_call(ball, pocket, safety, push_out));
                }
                if (const auto* error = std::get_if<MatchError>(&played))
                    raise_on(*error);
                return std::get<PlayedShot>(played);
            },
            py::arg("player"), py::arg("strike"), py::arg("ball") = 0, py::arg("pocket") = 0,
            py::arg("safety") = false, py::arg("push_out") = false)
        .def(
            "choose",
            [](Match& match, int player, const std::string& choice) {
                raise_on(match.choose(player, parse_or_raise(choice_names, choice, "choice")));
            },
            py::arg("player"), py::arg("choice"))
        .def(
            "next_rack", [](Match& match, int player) { raise_on(match.next_rack(player)); },
            py::arg("player"))
        .def(
            "play_computer",
            [](Match& match) -> py::object {
                if (!match.computer_to_act())
                    throw py::value_error("no computer is to act");
                std::optional<ComputerMove> move;
                {
                    // The GIL is kept while this object changes: another thread may be reading it.
                    move = match.computer_move();
                }
                if (!move)
                    throw py::value_error("the computer has no move");
                const int player = match.to_act();
                switch (move->kind) {
                case Pending::place:
                    raise_on(match.place(player, move->spot));
                    return py::none();
                case Pending::choose:
                    raise_on(match.choose(player, move->choice));
                    return py::none();
                default: {
                    std::variant<PlayedShot, MatchError> played = MatchError::none;
                    {
                        // The GIL is kept while this object changes: another thread may be reading
                        // it.
                        played = match.shoot(player, move->shot.strike, move->shot.call);
                    }
                    if (const auto* error = std::get_if<MatchError>(&played))
                        raise_on(*error);
                    return py::cast(std::get<PlayedShot>(played));
                }
                }
            },
            "Lets the computer to act take its action: a PlayedShot for a shot, None for a "
            "placement or a choice.")
        .def(
            "record", [](const Match& match) { return format_record(match.record()); },
            "The match's record, as `termpool replay` reads it.");
}

template <class T, std::size_t N> std::vector<std::string> names_list(const NameRow<T> (&t)[N]) {
    std::vector<std::string> out;
    for (const NameRow<T>& row : t)
        out.push_back(row.name);
    return out;
}

} // namespace

PYBIND11_MODULE(termpool, m) {
    m.doc() = "termpool: event-based pool and snooker physics, referees and matches.";
    m.attr("__version__") = TERMPOOL_VERSION;
    m.attr("physics_version") = physics_version;
    m.attr("EVENT_KINDS") = names_list(event_kind_names);
    m.attr("MOTION_STATES") = names_list(motion_state_names);
    m.attr("PARAMETERS") = std::vector<std::string>(std::begin(physics_parameter_names),
                                                    std::end(physics_parameter_names));
    m.attr("numpy") = python::numpy_present();
    bind_physics(m);
    bind_simulation(m);
    bind_rules(m);
}
