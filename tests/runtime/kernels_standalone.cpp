// The generated header compiles on its own, with every kernel instantiated for float and double,
// under -Wall -Wextra -Wpedantic -Werror and -Wdouble-promotion -Wconversion (a double literal in
// float code would promote and fail).
#include <billiards/kernel_list.hpp>
#include <billiards/kernels.hpp>

#include <limits>

namespace billiards::kernels {

// Every kernel the derivation emits, instantiated for float and double through the generated list
// (billiards/kernel_list.hpp), so a new kernel is compiled here without editing this file.
template float list::sum_of_every_kernel<float>(const float*) noexcept;
template double list::sum_of_every_kernel<double>(const double*) noexcept;
template float absolute_value<float>(float) noexcept;
template double absolute_value<double>(double) noexcept;
static_assert(smallest_normal<float>() == std::numeric_limits<float>::min());
static_assert(smallest_normal<double>() == std::numeric_limits<double>::min());
static_assert(infinity<float>() == std::numeric_limits<float>::infinity());
static_assert(infinity<double>() == std::numeric_limits<double>::infinity());

// constexpr: usable in constant expressions.
static_assert(elastic_normal_velocity_change(1.0f, 1.0f, 0.0f, 2.0f).first == 2.0f);
static_assert(elastic_normal_velocity_change(1.0, 1.0, 0.0, 2.0).second == -2.0);
static_assert(cushion_normal_velocity_change(3.0) == -6.0);
static_assert(approaching_direction_velocity_change(1.0, 1.0, 0.0, 1.0, 1.0, 1.0).first ==
              0.0);  // separating
static_assert(approaching_direction_velocity_change(1.0, 1.0, 0.0, -1.0, 1.0, 1.0).first == -1.0);

}  // namespace billiards::kernels
