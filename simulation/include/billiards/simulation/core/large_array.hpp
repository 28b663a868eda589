// An allocator for the large arrays of an event-driven simulation (billiards/simulation/gas.hpp): aligned to
// cache lines, and from 2 MiB up on huge-page boundaries with the kernel asked to back them with huge pages.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace billiards::simulation::detail {

/// std::allocator's interface. Arrays below 2 MiB are aligned to 64 bytes (a large std::vector's data
/// otherwise sit 16 bytes past a cache line). From 2 MiB up they are aligned to 2 MiB and, on Linux,
/// marked MADV_HUGEPAGE: where transparent huge pages are enabled "always" or on request ("madvise",
/// Debian's default), the kernel then backs them with 2 MiB pages. A simulation beyond the caches
/// reads its arrays at random; with 4 KiB pages (10^6 disks: about 40,000 of them) nearly every such
/// read also misses the address translation caches, and the profile showed the gas waiting on its own
/// prefetches, which cannot retire before their page walk. With huge pages (about 80) those walks go:
/// 10^6 disks 7 % and 18 % more collisions a second (medians of 6 and 7 runs of each build,
/// alternating), 10^6 spheres even. A hint: where the kernel declines, only the speed changes.
template <typename T>
struct LargeArray {
  using value_type = T;
  static constexpr std::size_t line = 64, huge_page = std::size_t{1} << 21;

  LargeArray() = default;
  template <typename U>
  LargeArray(const LargeArray<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T) - huge_page) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (bytes < huge_page) return static_cast<T*>(::operator new (bytes, std::align_val_t{line}));
    const std::size_t rounded = (bytes + huge_page - 1) / huge_page * huge_page;  // aligned_alloc's rule
    void* p = std::aligned_alloc(huge_page, rounded);
    if (p == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    ::madvise(p, rounded, MADV_HUGEPAGE);  // a request: its refusal is no error
#endif
    return static_cast<T*>(p);
  }

  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < huge_page)
      ::operator delete (p, std::align_val_t{line});
    else
      std::free(p);
  }

  template <typename U>
  bool operator==(const LargeArray<U>&) const noexcept {
    return true;
  }
};

/// A std::vector on LargeArray.
template <typename T>
using Array = std::vector<T, LargeArray<T>>;

}  // namespace billiards::simulation::detail
