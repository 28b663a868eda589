// The generated kernels inside CUDA kernels, float and double: compiled by the gpu/ test with nvcc
// (compile only: no GPU is needed).
#include <billiards/kernels.hpp>

namespace kernels = billiards::kernels;

template <typename Scalar>
__global__ void collide_all(const Scalar* m1, const Scalar* m2, const Scalar* v1n, const Scalar* v2n,
                            Scalar* dv1, Scalar* dv2, int count) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= count) return;
  const auto elastic = kernels::elastic_normal_velocity_change(m1[i], m2[i], v1n[i], v2n[i]);
  const auto restitution = kernels::normal_velocity_change(m1[i], m2[i], v1n[i], v2n[i], Scalar(0.5));
  const auto direction =
      kernels::direction_velocity_change(m1[i], m2[i], v1n[i], v2n[i], Scalar(2), Scalar(1));
  const auto approaching =
      kernels::approaching_direction_velocity_change(m1[i], m2[i], v1n[i], v2n[i], Scalar(2), Scalar(1));
  dv1[i] = elastic.first + restitution.first + direction.first + approaching.first +
           kernels::cushion_normal_velocity_change(v1n[i]);
  dv2[i] =
      elastic.second + restitution.second + direction.second + approaching.second +
      kernels::time_of_impact(m1[i], v1n[i], m2[i], v2n[i], Scalar(1));  // std::sqrt and +∞ on the device
}

template __global__ void collide_all<float>(const float*, const float*, const float*, const float*, float*,
                                            float*, int);
template __global__ void collide_all<double>(const double*, const double*, const double*, const double*,
                                             double*, double*, int);
