/// \file
/// The hard-sphere gas: N balls in a periodic box, 2-D or 3-D, run collision by collision (Gas<D>,
/// gas/gas.hpp), from a setup (GasSetup, gas/setup.hpp) or a lattice, and measured (gas::measure,
/// gas/measure.hpp). The engines' common vocabulary: docs/simulations.md.
#pragma once

#include <billiards/simulation/core/errors.hpp>
#include <billiards/simulation/gas/gas.hpp>
#include <billiards/simulation/gas/measure.hpp>
#include <billiards/simulation/gas/setup.hpp>
