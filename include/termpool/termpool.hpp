#pragma once
/// \file
/// The whole library in one header: the physics (simulator.hpp, table.hpp, params.hpp), the
/// games' rules and referees (rules.hpp, referee.hpp, game_registry.hpp), the match, records,
/// the computer players and the version. `pkg-config --cflags --libs termpool` gives what a
/// program needs to use it; the headers need C++20.

#include <termpool/assist.hpp>
#include <termpool/ball.hpp>
#include <termpool/break_off.hpp>
#include <termpool/computer.hpp>
#include <termpool/enum_names.hpp>
#include <termpool/event.hpp>
#include <termpool/game_registry.hpp>
#include <termpool/level.hpp>
#include <termpool/match.hpp>
#include <termpool/name_characters.hpp>
#include <termpool/params.hpp>
#include <termpool/practice.hpp>
#include <termpool/race.hpp>
#include <termpool/rack.hpp>
#include <termpool/record.hpp>
#include <termpool/referee.hpp>
#include <termpool/rules.hpp>
#include <termpool/rules_names.hpp>
#include <termpool/safe_player.hpp>
#include <termpool/setup.hpp>
#include <termpool/shot_facts.hpp>
#include <termpool/simulator.hpp>
#include <termpool/snooker_layout.hpp>
#include <termpool/spots.hpp>
#include <termpool/stats.hpp>
#include <termpool/table.hpp>
#include <termpool/table_physics.hpp>
#include <termpool/text_width.hpp>
#include <termpool/vec.hpp>
#include <termpool/version.hpp>
