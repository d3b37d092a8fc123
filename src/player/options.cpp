#include "player/options.hpp"

#include "player/player_name.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <termpool/race.hpp>

namespace termpool {

std::optional<int> parse_race_to(std::string_view text) {
    int n = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc{} || end != text.data() + text.size() || n < 1 || n > max_race_to)
        return std::nullopt;
    return n;
}

std::optional<int> parse_best_of(std::string_view text) {
    int n = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc{} || end != text.data() + text.size() || n < 1 ||
        n > best_of_for_race(max_race_to) || n % 2 == 0)
        return std::nullopt;
    return n;
}

std::optional<GameOptions> parse_game_options(const std::vector<std::string>& args,
                                              std::string& error, GameOptions o) {
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> const std::string* {
            if (i + 1 >= args.size()) {
                error = a + " needs a value";
                return nullptr;
            }
            return &args[++i];
        };
        if (a == "--ascii") {
            o.ascii = true;
        } else if (a == "--resume") {
            // The save is optional: a slot number or a file, never an option.
            o.resume = true;
            if (i + 1 < args.size() && !args[i + 1].empty() && !args[i + 1].starts_with("-"))
                o.resume_from = args[++i];
        } else if (a == "-h" || a == "--help") {
            o.help = true;
        } else if (a == "--friction") {
            // physical | decay K | constant A | combined K A, as in `termpool simulate`.
            const std::string* kind = value();
            if (!kind)
                return std::nullopt;
            const std::optional<FrictionKind> named = parse_friction_kind(*kind);
            if (!named) {
                error = "unknown friction model '" + *kind +
                        "' (physical, decay K, constant A or combined K A)";
                return std::nullopt;
            }
            std::vector<std::string_view> words{*kind};
            for (std::size_t c = 0; c < friction_constant_count(*named) && i + 1 < args.size(); ++c)
                words.push_back(args[++i]);
            auto model = parse_friction(words);
            if (const auto* problem = std::get_if<FrictionProblem>(&model);
                problem && problem->kind == FrictionProblem::Kind::missing_constant) {
                // The constants given are read in turn before the one missing is asked for.
                std::vector<std::string_view> padded = words;
                padded.resize(friction_constant_count(*named) + 1, "1");
                if (const auto padded_model = parse_friction(padded);
                    std::holds_alternative<FrictionProblem>(padded_model))
                    model = padded_model;
            }
            if (const auto* problem = std::get_if<FrictionProblem>(&model)) {
                const char* symbol = friction_constant_symbol(*named, problem->word - 1);
                error = problem->kind == FrictionProblem::Kind::missing_constant
                            ? "--friction " + *kind + " needs " + symbol
                            : std::string(symbol) + " must be a positive number";
                return std::nullopt;
            }
            o.setup.physics.friction = std::get<FrictionModel>(model);
        } else if (a == "--cue-ball-mass") {
            const std::string* v = value();
            if (!v)
                return std::nullopt;
            char* end = nullptr;
            const double kg = std::strtod(v->c_str(), &end);
            if (*end != '\0' || !(kg >= 0.05 && kg <= 1.0)) {
                error = "--cue-ball-mass takes kilograms between 0.05 and 1";
                return std::nullopt;
            }
            o.setup.physics.cue_ball_mass = kg;
        } else if (a == "--cue") {
            const std::string* v = value();
            if (!v)
                return std::nullopt;
            const std::optional<double> end_mass = parse_name(cue_names, *v);
            if (!end_mass) {
                error = "--cue takes standard, low-deflection or none";
                return std::nullopt;
            }
            o.setup.physics.cue_end_mass = *end_mass;
        } else if (a == "--vs-computer" || a == "--watch") {
            // The level is optional: take the next word only when it names one.
            std::optional<Level>& seat = a == "--watch" ? o.watch : o.computer;
            seat = o.default_level;
            if (i + 1 < args.size() && !args[i + 1].starts_with("--")) {
                const auto level = parse_level(args[i + 1]);
                if (!level) {
                    error = "unknown level '" + args[i + 1] + "' (easy, medium, hard or pro)";
                    return std::nullopt;
                }
                seat = *level;
                ++i;
            }
        } else if (a == "--player1" || a == "--player2") {
            const std::string* v = value();
            if (!v)
                return std::nullopt;
            std::string why;
            const auto name = clean_player_name(*v, why);
            if (!why.empty()) {
                error = a + ": " + why;
                return std::nullopt;
            }
            o.names[a == "--player1" ? 0 : 1] = name;
        } else if (a == "--game") {
            const std::string* v = value();
            if (!v)
                return std::nullopt;
            const auto g = parse_game_type(*v);
            if (!g) {
                error = "unknown game '" + *v + "' (8ball, 8ball-bar, 9ball, 10ball or snooker)";
                return std::nullopt;
            }
            o.setup.game = *g;
        } else if (a == "--table") {
            const std::string* v = value();
            if (!v)
                return std::nullopt;
            const std::optional<TableSize> size = parse_table_size(*v);
            if (!size) {
                error = "unknown table '" + *v + "' (7ft, 8ft, 9ft or snooker)";
                return std::nullopt;
            }
            o.setup.table = *size;
        } else if (a == "--seed") {
            // The first rack's seed, so that a game can be set up again exactly.
            const std::string* v = value();
            if (!v)
                return std::nullopt;
            std::uint64_t seed = 0;
            const auto [end, ec] = std::from_chars(v->data(), v->data() + v->size(), seed);
            if (ec != std::errc{} || end != v->data() + v->size()) {
                error = "--seed takes a whole number from 0 to 18446744073709551615";
                return std::nullopt;
            }
            o.seed = seed;
        } else if (a == "--race") {
            const std::string* v = value();
            if (!v)
                return std::nullopt;
            const auto n = parse_race_to(*v);
            if (!n) {
                error = "--race takes a number of racks from 1 to " + std::to_string(max_race_to) +
                        ", not '" + *v + "'";
                return std::nullopt;
            }
            o.race_to = *n;
        } else if (a == "--best-of") {
            // Snooker says a match of frames so: best of 5 is a race to 3.
            const std::string* v = value();
            if (!v)
                return std::nullopt;
            const auto n = parse_best_of(*v);
            if (!n) {
                error = "--best-of takes an odd number of frames from 1 to " +
                        std::to_string(best_of_for_race(max_race_to)) + ", not '" + *v + "'";
                return std::nullopt;
            }
            o.race_to = race_for_best_of(*n);
        } else if (a == "--assist") {
            const std::string* v = value();
            if (!v)
                return std::nullopt;
            const auto assist = parse_assist(*v);
            if (!assist) {
                error = "unknown assist '" + *v + "' (guided, standard or pro)";
                return std::nullopt;
            }
            o.assist = *assist;
        } else if (a == "--breaks") {
            const std::string* v = value();
            if (!v)
                return std::nullopt;
            const auto rule = parse_break_rule(*v);
            if (!rule) {
                error = "unknown break rule '" + *v + "' (alternate or winner)";
                return std::nullopt;
            }
            o.break_rule = *rule;
        } else {
            error = "unknown option '" + a + "'";
            return std::nullopt;
        }
    }
    // Watching means two computers: the second seat too, at the same level unless given.
    if (o.watch && !o.computer)
        o.computer = o.watch;
    return o;
}

} // namespace termpool
