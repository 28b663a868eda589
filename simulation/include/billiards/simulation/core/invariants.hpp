/// \file
/// The invariants' tolerances every engine shares.
#pragma once

namespace billiards::simulation {

/// The largest overlap allowed at an event, as a fraction of the radius (two balls, a ball and a
/// cushion, a ball and a jaw): every engine checks its events against it (Table, Shot) or measures
/// against it (Gas::largest_overlap).
inline constexpr double overlap_tolerance = 1e-9;

}  // namespace billiards::simulation
