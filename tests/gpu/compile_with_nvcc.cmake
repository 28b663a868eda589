# Compiles kernels.cu with nvcc (compile only; no GPU needed). Without nvcc the test is skipped
# (exit 77) with a message saying so. INCLUDE: the folder holding billiards/kernels.hpp; OUT: object.
find_program(NVCC nvcc HINTS /usr/local/cuda/bin ENV CUDA_HOME PATH_SUFFIXES bin)
if(NOT NVCC)
  message("skipped: nvcc not found (looked on PATH and in /usr/local/cuda/bin); the CUDA compile test needs it")
  cmake_language(EXIT 77)
endif()
execute_process(COMMAND ${NVCC} -std=c++20 -Werror all-warnings -I${INCLUDE} -c ${CMAKE_CURRENT_LIST_DIR}/kernels.cu
                        -o ${OUT} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "nvcc could not compile the kernels in CUDA code (${code}):\n${out}${err}")
endif()
message("compiled the float and double kernels in a __global__ function with ${NVCC}")
