/// \file
/// The pool shot: a shot on a pool table from the cue to rest (Shot), its table and physics presets
/// and racks (shot/pool_table.hpp), its events (shot/event.hpp) and its parts — detection, evolution,
/// resolution, checks (shot/*.hpp). The engines' common vocabulary: docs/simulations.md.
#pragma once

#include <billiards/simulation/core/errors.hpp>
#include <billiards/simulation/shot/event.hpp>
#include <billiards/simulation/shot/layouts.hpp>
#include <billiards/simulation/shot/pool_table.hpp>
#include <billiards/simulation/shot/shot.hpp>
