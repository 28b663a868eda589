// The gas engines' loops beyond the caches, compiled once for the project's programs and tests
// (billiards_gas_loops; see the end of billiards/simulation/gas/gas.hpp).
#include <billiards/simulation/gas.hpp>

namespace billiards::simulation::detail {
template std::uint64_t GasEngine<2, CellGas<2>>::run_beyond_caches(std::uint64_t, double, NoCallback&);
template std::uint64_t GasEngine<3, CellGas<3>>::run_beyond_caches(std::uint64_t, double, NoCallback&);
template std::uint64_t GasEngine<2, ListGas<2>>::run_beyond_caches(std::uint64_t, double, NoCallback&);
template std::uint64_t GasEngine<3, ListGas<3>>::run_beyond_caches(std::uint64_t, double, NoCallback&);
template std::uint64_t GasEngine<2, CellGas<2>>::run_beyond_caches(std::uint64_t, double,
                                                                   GasEngine<2, CellGas<2>>::ErasedCallback&);
template std::uint64_t GasEngine<3, CellGas<3>>::run_beyond_caches(std::uint64_t, double,
                                                                   GasEngine<3, CellGas<3>>::ErasedCallback&);
template std::uint64_t GasEngine<2, ListGas<2>>::run_beyond_caches(std::uint64_t, double,
                                                                   GasEngine<2, ListGas<2>>::ErasedCallback&);
template std::uint64_t GasEngine<3, ListGas<3>>::run_beyond_caches(std::uint64_t, double,
                                                                   GasEngine<3, ListGas<3>>::ErasedCallback&);
}  // namespace billiards::simulation::detail
