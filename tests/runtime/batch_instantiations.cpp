// The batch loop instantiated for float and double in 3-D: compiled by the vectorisation check.
#include <billiards/batch.hpp>

template void billiards::collide_batch<double, 3>(std::span<const double>,
                                                  const billiards::Components<double, 3>&,
                                                  std::span<const double>,
                                                  const billiards::Components<double, 3>&,
                                                  const billiards::Components<const double, 3>&);
template void billiards::collide_batch<float, 3>(std::span<const float>,
                                                 const billiards::Components<float, 3>&,
                                                 std::span<const float>,
                                                 const billiards::Components<float, 3>&,
                                                 const billiards::Components<const float, 3>&);
