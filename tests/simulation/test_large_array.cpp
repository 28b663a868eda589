// billiards/simulation/core/large_array.hpp: the alignment it promises on either side of 2 MiB, memory that
// holds what is written, and a clear error for a size no address space holds.
#include <billiards/simulation/core/large_array.hpp>

#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>
#include <new>

using billiards::simulation::detail::Array;
using billiards::simulation::detail::LargeArray;

TEST_CASE("large arrays are aligned to cache lines, and from 2 MiB up to huge pages") {
  for (const std::size_t n : {std::size_t{1}, std::size_t{1000}, (std::size_t{1} << 18) - 1,
                              std::size_t{1} << 18, (std::size_t{1} << 18) + 1, std::size_t{3} << 20}) {
    INFO(n << " doubles");
    Array<double> a(n, 0.0);
    const auto address = reinterpret_cast<std::uintptr_t>(a.data());
    const std::size_t alignment =
        n * sizeof(double) < LargeArray<double>::huge_page ? 64 : std::size_t{1} << 21;
    CHECK(address % alignment == 0);
    for (std::size_t i = 0; i < n; i += 4099) a[i] = static_cast<double>(i);
    for (std::size_t i = 0; i < n; i += 4099) CHECK(a[i] == static_cast<double>(i));
    a.resize(n + 1, 1.0);  // a move to a new block, freed by the same rule it was taken by
    CHECK(a.back() == 1.0);
  }
}

TEST_CASE("a large array of more bytes than an address holds is refused") {
  LargeArray<double> allocator;
  CHECK_THROWS_AS(allocator.allocate(std::numeric_limits<std::size_t>::max() / 4), std::bad_array_new_length);
}
