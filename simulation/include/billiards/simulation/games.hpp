/// \file
/// The rules of the games on a shot's events: 9-ball and 8-ball after the WPA's World Standardized
/// Rules (games/nine_ball.hpp, games/eight_ball.hpp), snooker after the WPBSA's (games/snooker.hpp),
/// three-cushion after the UMB's (games/three_cushion.hpp), what they read of a shot and what they decide
/// (games/rules.hpp), and a game played shot by shot (games/game.hpp). Which rules are in: docs/games.md.
#pragma once

#include <billiards/simulation/games/eight_ball.hpp>
#include <billiards/simulation/games/game.hpp>
#include <billiards/simulation/games/nine_ball.hpp>
#include <billiards/simulation/games/rules.hpp>
#include <billiards/simulation/games/snooker.hpp>
#include <billiards/simulation/games/three_cushion.hpp>
