// billiards::collide_batch: many collisions at once over structure-of-arrays spans, written so that
// the compiler vectorises the loop (a straight-line body: per block of pairs, the generated plain kernel
// where every mass lies in its range, else the generated full kernel, whose one branch is a select).
#pragma once

#include <billiards/detail/arithmetic.hpp>
#include <billiards/kernels.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>

namespace billiards {

/// One coordinate per array: `component[k][i]` is coordinate k of item i.
template <typename Scalar, std::size_t Dimension>
using Components = std::array<std::span<Scalar>, Dimension>;

namespace detail {

/// collide_batch's block: 4096 pairs, whose masses are tested together and whose arrays stay in the
/// caches between the test and the pass (the masses in the second level at most). Beyond the caches
/// the hardware prefetcher streams the arrays; the test reads only the masses ahead of the pass, and
/// each block boundary restarts the streams of the other arrays, so the larger the block the less the
/// streams stall: measured pinned, side by side, 4096 pairs ran 10–25 % more pairs a second than 1024
/// at 10^6 and 10^7, and as fast in cache. (Until this release the batch also asked memory for the next
/// block's arrays, `__builtin_prefetch`, from 2^17 pairs up; once each pair's components were read once,
/// that prefetch cost more than it gave: 34–40 against 41–50 GB/s in double at 10^6 pairs.)
inline constexpr std::size_t batch_block = 4096;

}  // namespace detail

/// \brief The paper's elastic collision for `m1.size()` pairs at once, updating the velocities in place.
///
/// Pair i has masses m1[i], m2[i], velocities (v1[0][i], …, v1[D−1][i]) and likewise v2, and unit
/// contact normal (n[0][i], …); afterwards v1 and v2 hold x1 and x2 exactly as billiards::collide
/// would compute them under the same compiler flags, bit for bit (the same generated kernels: for each
/// block of 4096 pairs whose masses kernels::within_plain_mass_range all accepts,
/// kernels::plain_elastic_normal_velocity_change, as kernels::elastic_normal_velocity_change takes it
/// there; for any other block that kernel itself; both vectorised; and the same dot product and
/// update, detail/arithmetic.hpp; tested on random data with and without -march=native). A mass may
/// be +∞. No allocation. The arrays must not overlap one another.
/// \throws std::invalid_argument when a span's length differs from m1's (checked once, before any
///         update, so nothing is half-updated).
#if defined(__clang__)
// Where the loop cannot be vectorised anyway (sanitizer builds), clang's "loop not vectorized" is no
// error in the user's code.
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wpass-failed"
#endif
template <typename Scalar, std::size_t Dimension>
void collide_batch(std::span<const Scalar> m1, const Components<Scalar, Dimension>& v1,
                   std::span<const Scalar> m2, const Components<Scalar, Dimension>& v2,
                   const Components<const Scalar, Dimension>& n) {
  const std::size_t count = m1.size();
  const auto require = [count](std::size_t size, const char* name) {
    if (size != count) {
      throw std::invalid_argument("billiards::collide_batch: " + std::string(name) + " has " +
                                  std::to_string(size) + " items, expected " + std::to_string(count) +
                                  " (the length of m1)");
    }
  };
  require(m2.size(), "m2");
  for (std::size_t k = 0; k < Dimension; ++k) {
    require(v1[k].size(), "v1");
    require(v2[k].size(), "v2");
    require(n[k].size(), "n");
  }
  Scalar* __restrict x1[Dimension];
  Scalar* __restrict x2[Dimension];
  const Scalar* __restrict normal[Dimension];
  for (std::size_t k = 0; k < Dimension; ++k) {
    x1[k] = v1[k].data();
    x2[k] = v2[k].data();
    normal[k] = n[k].data();
  }
  const Scalar* __restrict mass1 = m1.data();
  const Scalar* __restrict mass2 = m2.data();
  // One pass over pairs [begin, end) through `kernel` (a generated kernel of the masses and the normal
  // velocities).
  const auto pass = [&](std::size_t begin, std::size_t end, auto kernel) {
  // The arrays do not overlap (a documented precondition). The compilers must be told: otherwise they
  // would need a run-time overlap test for every pair of the 3D + 2 arrays, more than they are willing
  // to emit (GCC stops at 10), and leave the loop scalar.
#if defined(__clang__)
#pragma clang loop vectorize(assume_safety)
#elif defined(__GNUC__)
#pragma GCC ivdep
#endif
    for (std::size_t i = begin; i < end; ++i) {  // the batch loop: vectorised (see docs/runtime.md)
      // The same dot product and the same update as billiards::collide (detail/arithmetic.hpp), so the
      // bits agree under the same flags. Each component is read once, into a local, before anything is
      // written: the compilers do not take __restrict on these arrays of pointers as a promise that a
      // store to x1[k][i] leaves normal[k][i] unchanged, and the loop that read the arrays in place
      // loaded each normal component two and three times a pair (a third slower in cache).
      Scalar a[Dimension], b[Dimension], d[Dimension];
      for (std::size_t k = 0; k < Dimension; ++k) {
        a[k] = x1[k][i];
        b[k] = x2[k][i];
        d[k] = normal[k][i];
      }
      const auto normal_at = [&](std::size_t k) { return d[k]; };
      const Scalar relative = detail::difference_dot<Dimension>(
          [&](std::size_t k) { return a[k]; }, [&](std::size_t k) { return b[k]; }, normal_at);
      const auto change = kernel(mass1[i], mass2[i], Scalar(0), relative);
      for (std::size_t k = 0; k < Dimension; ++k) {
        x1[k][i] = detail::plus_multiple(a[k], change.first, d[k]);
        x2[k][i] = detail::plus_multiple(b[k], change.second, d[k]);
      }
    }
  };
  // In blocks small enough to stay in the caches: where every pair's masses lie in the plain
  // form's range, the plain kernel that elastic_normal_velocity_change itself takes there (two divisions
  // by one sum); otherwise elastic_normal_velocity_change (its ratio form for the pairs outside). The
  // range test (kernels::within_plain_mass_range, on the masses' bits: a few integer operations a pair)
  // reads two of the 6D + 2 arrays, which the pass then finds in that cache.
  constexpr std::size_t block = detail::batch_block;
  for (std::size_t begin = 0; begin < count; begin += block) {
    const std::size_t end = count - begin < block ? count : begin + block;
    unsigned outside = 0;
    for (std::size_t i = begin; i < end; ++i) {
      outside |= kernels::within_plain_mass_range(mass1[i], mass2[i]) ? 0u : 1u;
    }
    if (outside == 0) {
      pass(begin, end, [](Scalar a, Scalar b, Scalar u, Scalar w) {
        return kernels::plain_elastic_normal_velocity_change(a, b, u, w);
      });
    } else {
      pass(begin, end, [](Scalar a, Scalar b, Scalar u, Scalar w) {
        return kernels::elastic_normal_velocity_change(a, b, u, w);
      });
    }
  }
}

#if defined(__clang__)
#pragma clang diagnostic pop
#endif

}  // namespace billiards
