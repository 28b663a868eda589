/// \file
/// The frictionless table: N equal balls on a rectangular table with cushions, run event by event
/// (Table, table/table.hpp), from a setup built in code or read from a file (TableSetup,
/// table/setup.hpp). The engines' common vocabulary: docs/simulations.md.
#pragma once

#include <billiards/simulation/core/errors.hpp>
#include <billiards/simulation/table/setup.hpp>
#include <billiards/simulation/table/table.hpp>
