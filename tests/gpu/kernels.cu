// The generated kernels inside CUDA kernels, float and double: compiled by the gpu/ test with nvcc
// (compile only: no GPU is needed). Every kernel of every model is called through its generated list
// (billiards/kernel_list.hpp, billiards/spin_kernel_list.hpp), so a new kernel is compiled for the
// device without editing this file.
#include <billiards/kernel_list.hpp>
#include <billiards/spin_kernel_list.hpp>

namespace list = billiards::kernels::list;
namespace spin_list = billiards::kernels::spin::list;

template <typename Scalar>
__global__ void every_kernel(const Scalar* arguments, Scalar* sums, int count) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= count) return;
  // std::sqrt, +∞ and the smallest normal number on the device.
  sums[i] = list::sum_of_every_kernel(arguments + i * static_cast<int>(list::largest_arity));
}

template <typename Scalar>
__global__ void every_spin_kernel(const Scalar* arguments, Scalar* sums, int count) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= count) return;
  sums[i] = spin_list::sum_of_every_kernel(arguments + i * static_cast<int>(spin_list::largest_arity));
}

template __global__ void every_kernel<float>(const float*, float*, int);
template __global__ void every_kernel<double>(const double*, double*, int);
template __global__ void every_spin_kernel<float>(const float*, float*, int);
template __global__ void every_spin_kernel<double>(const double*, double*, int);
