// The text form of a game record, and its replay.
#include "../support/random.hpp"
#include "../support/state_digest.hpp"
#include "../support/text_lines.hpp"
#include "../support/text_numbers.hpp"
#include <algorithm>
#include <charconv>
#include <cmath>
#include <termpool/game_registry.hpp>
#include <termpool/record.hpp>
#include <termpool/rules_names.hpp>

namespace termpool {
namespace {

std::string number(double v) {
    return format_double(v); // the one text of state that reads back exactly
}

std::optional<double> to_double(std::string_view s) {
    double v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc{} || end != s.data() + s.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::optional<std::uint64_t> to_u64(std::string_view s) {
    std::uint64_t v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc{} || end != s.data() + s.size())
        return std::nullopt;
    return v;
}

// The name is the rest of the line after the keyword: names may hold spaces.
std::string rest_after(std::string_view line, std::string_view keyword) {
    std::string_view rest = line.substr(line.find(keyword) + keyword.size());
    while (!rest.empty() && rest.front() == ' ')
        rest.remove_prefix(1);
    return std::string(rest);
}

// Lines that version 1 did not have: a record without them is written as version 1, so that a
// single game reads in older builds.
bool needs_version_2(const GameRecord& r) {
    return r.race_to > 1 || std::any_of(r.actions.begin(), r.actions.end(), [](const auto& a) {
               return a.kind == RecordedAction::Kind::rack;
           });
}

// What version 2 did not have: a cue other than the standard shaft, a raised cue.
bool needs_version_3(const GameRecord& r) {
    return r.setup.physics.cue_end_mass != standard_shaft_end_mass ||
           std::any_of(r.actions.begin(), r.actions.end(), [](const auto& a) {
               return a.kind == RecordedAction::Kind::shot && a.strike.elevation_deg != 0;
           });
}

int version_needed(const GameRecord& r) {
    if (r.check && r.check->running)
        return 6;
    if (r.assist != Assist::standard)
        return 5;
    if (r.check) // read from a record of version 4 or 5 and written back as it was
        return 4;
    return needs_version_3(r) ? 3 : needs_version_2(r) ? 2 : 1;
}

// A check's hash: exactly the 16 lower-case hex digits digest_hex writes.
std::optional<std::uint64_t> to_hash(std::string_view s) {
    if (s.size() != 16 || std::any_of(s.begin(), s.end(), [](char c) {
            return !((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'));
        }))
        return std::nullopt;
    std::uint64_t v = 0;
    std::from_chars(s.data(), s.data() + s.size(), v, 16);
    return v;
}

std::string cue_text(double end_mass) {
    const char* name = name_of(cue_names, end_mass, nullptr);
    return name ? name : number(end_mass);
}

// A number of a version 6 record's header: in the one text the writer gives it.
std::optional<double> to_canonical_double(std::string_view s) {
    const auto v = parse_canonical_double(s);
    return v && std::isfinite(*v) ? v : std::nullopt;
}

std::optional<double> to_cue_end_mass(std::string_view s, bool canonical) {
    if (const auto named = parse_name(cue_names, s))
        return named;
    const auto m = canonical ? to_canonical_double(s) : to_double(s);
    if (!m || *m < 0)
        return std::nullopt;
    return m;
}

// An action line's fields: the action, or what is wrong with it; nothing when the fields are
// not an action line (another key, or the wrong number of fields).
std::optional<std::variant<RecordedAction, std::string>>
read_action(const std::vector<std::string_view>& f) {
    const std::string_view key = f[0];
    auto want = [&](std::size_t n) { return f.size() == n; };
    RecordedAction a;
    if (key == "rack" && want(3)) {
        if (f[1] != "1" && f[1] != "2")
            return "rack breaker must be 1 or 2";
        const auto s = to_u64(f[2]);
        if (!s)
            return "bad rack seed";
        a.kind = RecordedAction::Kind::rack;
        a.breaker = f[1][0] - '0';
        a.seed = *s;
        return a;
    }
    if (key == "place" && want(3)) {
        const auto x = to_double(f[1]), y = to_double(f[2]);
        if (!x || !y)
            return "bad place coordinates";
        a.kind = RecordedAction::Kind::place;
        a.place = {*x, *y};
        return a;
    }
    if (key == "choose" && want(2)) {
        const auto c = parse_name(choice_names, f[1]);
        if (!c)
            return "unknown choice '" + std::string(f[1]) + "'";
        a.kind = RecordedAction::Kind::choose;
        a.choice = *c;
        return a;
    }
    if (key != "shot" || f.size() < 5)
        return std::nullopt;
    a.kind = RecordedAction::Kind::shot;
    const auto v = to_double(f[1]), phi = to_double(f[2]), side = to_double(f[3]),
               follow = to_double(f[4]);
    if (!v || !phi || !side || !follow)
        return "bad shot numbers";
    if (*v < 0 || *v > max_strike_speed || std::abs(*side) > 0.5 || std::abs(*follow) > 0.5)
        return "shot out of range";
    a.strike = {*v, *phi, *side, *follow};
    std::size_t i = 5;
    while (i < f.size()) {
        if (f[i] == "elevation" && i + 1 < f.size()) {
            const auto e = to_double(f[i + 1]);
            if (!e || *e < 0 || *e > max_cue_elevation_deg)
                return "bad elevation";
            a.strike.elevation_deg = *e;
            i += 2;
        } else if (f[i] == "safety") {
            a.call.call.safety = true;
            ++i;
        } else if (f[i] == "push-out") {
            a.call.push_out = true;
            ++i;
        } else if (f[i] == "call" && i + 2 < f.size()) {
            const auto ball = to_u64(f[i + 1]), pocket = to_u64(f[i + 2]);
            // Snooker's nominations reach ball 21 and may leave the pocket out (0); a pool
            // record is held to 1-15 and 1-6 once its game is known (parse_record).
            if (!ball || !pocket || *ball < 1 || *ball > 21 || *pocket > 6)
                return "bad call";
            a.call.call.ball = static_cast<int>(*ball);
            a.call.call.pocket = static_cast<int>(*pocket);
            i += 3;
        } else {
            return "unknown shot field '" + std::string(f[i]) + "'";
        }
    }
    return a;
}

} // namespace

std::string format_action(const RecordedAction& a) {
    switch (a.kind) {
    case RecordedAction::Kind::place:
        return "place " + number(a.place.x) + " " + number(a.place.y);
    case RecordedAction::Kind::choose:
        return std::string("choose ") + choice_name(a.choice);
    case RecordedAction::Kind::shot: {
        std::string out = "shot " + number(a.strike.speed) + " " + number(a.strike.angle_deg) +
                          " " + number(a.strike.side) + " " + number(a.strike.follow);
        if (a.strike.elevation_deg != 0)
            out += " elevation " + number(a.strike.elevation_deg);
        if (a.call.call.safety)
            out += " safety";
        else if (a.call.call.ball != 0)
            out += " call " + std::to_string(a.call.call.ball) + " " +
                   std::to_string(a.call.call.pocket);
        if (a.call.push_out)
            out += " push-out";
        return out;
    }
    case RecordedAction::Kind::rack:
        return "rack " + std::to_string(a.breaker) + " " + std::to_string(a.seed);
    }
    return {};
}

std::string format_record(const GameRecord& r) {
    std::string out = "termpool-record " + std::to_string(version_needed(r)) + "\n";
    out += std::string("game ") + game_type_name(r.setup.game) + "\n";
    out += std::string("table ") + table_size_name(r.setup.table) + "\n";
    out += "seed " + std::to_string(r.seed) + "\n";
    out += "breaker " + std::to_string(r.breaker) + "\n";
    for (int p = 0; p < 2; ++p) {
        out += "player" + std::to_string(p + 1) + " " + r.names[p] + "\n";
        if (r.computers[p])
            out += "computer" + std::to_string(p + 1) + " " + level_name(*r.computers[p]) + "\n";
    }
    if (r.setup.physics.friction.kind != FrictionKind::physical)
        out += "friction " + format_friction(r.setup.physics.friction) + "\n";
    if (r.setup.physics.cue_ball_mass > 0)
        out += "cue-ball-mass " + number(r.setup.physics.cue_ball_mass) + "\n";
    if (r.setup.physics.cue_end_mass != standard_shaft_end_mass)
        out += "cue " + cue_text(r.setup.physics.cue_end_mass) + "\n";
    if (r.race_to > 1) {
        out += "race " + std::to_string(r.race_to) + "\n";
        out += std::string("breaks ") + break_rule_name(r.break_rule) + "\n";
    }
    if (r.assist != Assist::standard)
        out += std::string("assist ") + assist_name(r.assist) + "\n";
    if (r.check)
        out += "physics " + std::to_string(r.check->physics_version) + "\n";
    for (const RecordedAction& a : r.actions)
        out += format_action(a) + "\n";
    if (r.check)
        out += "check " + digest_hex(r.check->hash) + "\n";
    out += "end\n";
    return out;
}

std::variant<GameRecord, RecordError> parse_record(std::string_view text) {
    // A last line without its newline, other than "end", is where a write was cut off.
    if (!text.empty() && text.back() != '\n') {
        const std::size_t start =
            text.rfind('\n') == std::string_view::npos ? 0 : text.rfind('\n') + 1;
        const std::vector<std::string_view> last = split_fields(text.substr(start));
        if (!(last.size() == 1 && last[0] == "end")) {
            const int line = 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
            return RecordError{line, "truncated: the last line is incomplete"};
        }
    }
    GameRecord r;
    int line_number = 0;
    bool header = false, ended = false, checked = false;
    std::uint64_t version = 0;
    std::optional<int> physics;
    bool assist_seen = false; // a second assist line would silently win
    // Version 6 holds every number to its one text (older builds wrote nothing else, but
    // older versions may have been written by hand, and are read as they always were).
    const auto whole = [&version](std::string_view s) {
        return version >= 6 ? parse_canonical_uint64(s) : to_u64(s);
    };
    const auto real = [&version](std::string_view s) {
        return version >= 6 ? to_canonical_double(s) : to_double(s);
    };
    for (const TextLine& text_line : text_lines(text)) {
        const std::string_view line = text_line.text;
        line_number = text_line.number;
        const std::vector<std::string_view> f = split_fields(line);
        if (f.empty())
            continue;
        auto fail = [&](std::string message) {
            return RecordError{line_number, std::move(message)};
        };
        if (ended)
            return fail("text after 'end'");
        if (!header) {
            if (f[0] != "termpool-record")
                return fail("not a termpool record");
            const auto v = f.size() == 2 ? to_u64(f[1]) : std::nullopt;
            if (!v)
                return fail("record version missing");
            if (*v > static_cast<std::uint64_t>(record_version))
                return fail("record version " + std::to_string(*v) + " is newer than this " +
                            "termpool reads (" + std::to_string(record_version) + ")");
            header = true;
            version = *v;
            continue;
        }
        const std::string_view key = f[0];
        auto want = [&](std::size_t n) { return f.size() == n; };
        if (version < 2 && (key == "race" || key == "breaks" || key == "rack"))
            return fail("'" + std::string(key) + "' lines need record version 2");
        if (version < 3 && key == "cue")
            return fail("'cue' lines need record version 3");
        if (version < 4 && (key == "physics" || key == "check"))
            return fail("'" + std::string(key) + "' lines need record version 4");
        if (version < 5 && key == "assist")
            return fail("'assist' lines need record version 5");
        if (checked && key != "end")
            return fail("only 'end' may follow the 'check' line");
        if (key == "game" && want(2)) {
            const auto g = parse_game_type(std::string(f[1]));
            if (!g)
                return fail("unknown game '" + std::string(f[1]) + "'");
            r.setup.game = *g;
        } else if (key == "table" && want(2)) {
            const std::optional<TableSize> size = parse_table_size(f[1]);
            if (!size)
                return fail("unknown table '" + std::string(f[1]) + "'");
            r.setup.table = *size;
        } else if (key == "seed" && want(2)) {
            const auto s = whole(f[1]);
            if (!s)
                return fail("bad seed");
            r.seed = *s;
        } else if (key == "breaker" && want(2)) {
            if (f[1] != "1" && f[1] != "2")
                return fail("breaker must be 1 or 2");
            r.breaker = f[1][0] - '0';
        } else if ((key == "player1" || key == "player2") && f.size() >= 2) {
            std::string name = rest_after(line, key);
            while (!name.empty() && (name.back() == ' ' || name.back() == '\t'))
                name.pop_back();
            if (!valid_player_name(name))
                return fail("a player's name must be text without control characters, at most " +
                            std::to_string(max_player_name_bytes) + " bytes");
            r.names[key.back() - '1'] = name;
        } else if ((key == "computer1" || key == "computer2") && want(2)) {
            const auto level = parse_level(std::string(f[1]));
            if (!level)
                return fail("unknown level '" + std::string(f[1]) + "'");
            r.computers[key.back() - '1'] = *level;
        } else if (key == "friction" && f.size() >= 3) {
            // A line names a model and at least one constant (physical is written as no line).
            if (const auto k = real(f[2]); !k || *k <= 0)
                return fail("friction constants must be positive numbers");
            const auto model = parse_friction(std::span(f).subspan(1));
            if (const auto* problem = std::get_if<FrictionProblem>(&model))
                return fail(problem->kind == FrictionProblem::Kind::not_positive ||
                                    problem->kind == FrictionProblem::Kind::not_finite ||
                                    problem->kind == FrictionProblem::Kind::not_a_number
                                ? "friction constants must be positive numbers"
                                : "bad friction line");
            // A record writes its numbers without a '+': read them back that way only.
            if (std::any_of(f.begin() + 2, f.end(),
                            [&real](std::string_view w) { return !real(w); }))
                return fail("friction constants must be positive numbers");
            r.setup.physics.friction = std::get<FrictionModel>(model);
        } else if (key == "cue-ball-mass" && want(2)) {
            const auto m = real(f[1]);
            if (!m || *m <= 0)
                return fail("cue-ball-mass must be a positive number");
            r.setup.physics.cue_ball_mass = *m;
        } else if (key == "cue" && want(2)) {
            const auto m = to_cue_end_mass(f[1], version >= 6);
            if (!m)
                return fail("cue must be standard, low-deflection, none or an end mass in kg");
            r.setup.physics.cue_end_mass = *m;
        } else if (key == "race" && want(2)) {
            const auto n = whole(f[1]);
            if (!n || *n < 1 || *n > static_cast<std::uint64_t>(max_race_to))
                return fail("race must be a number of racks from 1 to " +
                            std::to_string(max_race_to));
            r.race_to = static_cast<int>(*n);
        } else if (key == "breaks" && want(2)) {
            const auto rule = parse_break_rule(f[1]);
            if (!rule)
                return fail("unknown break rule '" + std::string(f[1]) + "' (alternate or winner)");
            r.break_rule = *rule;
        } else if (key == "assist" && want(2)) {
            if (assist_seen)
                return fail("a second 'assist' line");
            assist_seen = true;
            const auto assist = parse_assist(f[1]);
            if (!assist)
                return fail("unknown assist '" + std::string(f[1]) + "' (guided, standard or pro)");
            r.assist = *assist;
        } else if (key == "physics" && want(2)) {
            if (physics)
                return fail("a second 'physics' line");
            if (!r.actions.empty())
                return fail("the 'physics' line must come before the actions");
            const auto v = whole(f[1]);
            if (!v || *v < 1 || *v > 1000000)
                return fail("physics must be a version number");
            physics = static_cast<int>(*v);
        } else if (key == "check" && want(2)) {
            const auto hash = to_hash(f[1]);
            if (!hash)
                return fail("a check is 16 hexadecimal digits (0-9, a-f)");
            if (!physics)
                return fail("a 'check' line needs a 'physics' line");
            r.check = RecordCheck{*physics, *hash, line_number, version >= 6};
            checked = true;
        } else if (auto action = read_action(f)) {
            if (const std::string* problem = std::get_if<std::string>(&*action))
                return fail(*problem);
            if (version < 3 && std::get<RecordedAction>(*action).strike.elevation_deg != 0)
                return fail("a shot's elevation needs record version 3");
            // One text per action: the check covers the action as written, and a second
            // spelling of it ("1E-05" for "1e-05") would pass unseen.
            if (const std::string written = format_action(std::get<RecordedAction>(*action));
                version >= 6 && line != written)
                return fail("a version 6 record writes this action as '" + written + "'");
            std::get<RecordedAction>(*action).line = line_number;
            r.actions.push_back(std::get<RecordedAction>(*action));
        } else if (key == "end" && want(1)) {
            ended = true;
        } else {
            return fail("unknown or malformed line '" + std::string(key) + "'");
        }
    }
    if (!header)
        return RecordError{std::max(line_number, 1), "empty: not a termpool record"};
    if (!ended)
        return RecordError{line_number, "truncated: no 'end' line"};
    if (physics && !r.check)
        return RecordError{line_number, "a 'physics' line needs a 'check' line before 'end'"};
    for (const RecordedAction& a : r.actions)
        if (a.kind == RecordedAction::Kind::shot && a.call.call.ball != 0 &&
            !call_fits(game_row(r.setup.game), a.call.call))
            return RecordError{a.line, "bad call"};
    return r;
}

bool valid_player_name(std::string_view name) {
    return !name.empty() && name.size() <= max_player_name_bytes && name.front() != ' ' &&
           name.back() != ' ' && printable_characters(name).has_value();
}

std::variant<RecordedAction, RecordError> parse_action(std::string_view line) {
    const std::vector<std::string_view> f = split_fields(strip_comment(line));
    auto action = f.empty() ? std::nullopt : read_action(f);
    if (!action)
        return RecordError{1, "not an action line"};
    if (const std::string* problem = std::get_if<std::string>(&*action))
        return RecordError{1, *problem};
    return std::get<RecordedAction>(*action);
}

std::uint64_t rack_seed(std::uint64_t record_seed, int rack) {
    if (rack <= 1)
        return record_seed;
    Random mix(record_seed ^ (static_cast<std::uint64_t>(rack) << 40));
    return mix.next();
}

RecordedAction rack_action(const GameRecord& record, int rack, int breaker) {
    RecordedAction a;
    a.kind = RecordedAction::Kind::rack;
    a.breaker = breaker;
    a.seed = rack_seed(record.seed, rack);
    return a;
}

} // namespace termpool
