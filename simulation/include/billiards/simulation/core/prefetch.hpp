// A memory prefetch the optimiser keeps.
#pragma once

namespace billiards::simulation::detail {

/// Asks memory for the cache line at `p` (a hint: GCC's and clang's __builtin_prefetch; nothing elsewhere).
/// GCC deletes a loop whose only effect is a prefetch — a hint is no side effect, and such a loop may be
/// assumed to end (C++'s forward-progress rule) — so each prefetch also carries an empty volatile asm, which
/// the loop must keep. Seen: a look-ahead over the event calendar's lists compiled to no prefetch at
/// all without it.
inline void prefetch([[maybe_unused]] const void* p) {
#if defined(__GNUC__)
  __builtin_prefetch(p);
  asm volatile("" : : "r"(p));
#endif
}

}  // namespace billiards::simulation::detail
