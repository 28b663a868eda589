# Compiles SOURCE at -O3 with the compiler's vectorisation report and requires it to name the batch
# loop of billiards/batch.hpp: the line marked "the batch loop", not just any loop of the header (the
# short loops that copy the span pointers vectorise too). CXX, COMPILER_ID (GNU or Clang), INCLUDES (a
# ;-list of -I flags), HEADER (batch.hpp).
#
# Both compilers are asked at the x86-64 baseline (SSE2), the hardest case: GCC does not if-convert an
# operation that may trap unless the target can mask it (AVX-512), so the kernels' guards must select
# values, never make an operation conditional (see derive/derivation.cpp, the emitted kernels).
file(READ ${HEADER} text)
string(FIND "${text}" "// the batch loop" marker)
if(marker EQUAL -1)
  message(FATAL_ERROR "${HEADER} has no line marked '// the batch loop'")
endif()
string(SUBSTRING "${text}" 0 ${marker} before)
string(REGEX MATCHALL "\n" newlines "${before}")
list(LENGTH newlines loop_line)
math(EXPR loop_line "${loop_line} + 1")
if(COMPILER_ID STREQUAL "GNU")
  set(flags -fopt-info-vec-optimized)
  set(pattern "batch\\.hpp:${loop_line}:[0-9]+: optimized: loop vectorized")
else()
  set(flags -Rpass=loop-vectorize)
  set(pattern "batch\\.hpp:${loop_line}:[0-9]+: remark: vectorized loop")
endif()
execute_process(COMMAND ${CXX} -std=c++20 -O3 ${flags} ${INCLUDES} -c ${SOURCE} -o ${OUT}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the batch loop did not compile (${code}):\n${out}${err}")
endif()
if(NOT "${out}${err}" MATCHES "${pattern}")
  message(FATAL_ERROR "the vectorisation report does not name the batch loop (batch.hpp:${loop_line}):\n${out}${err}")
endif()
string(REGEX MATCH "${pattern}[^\n]*" line "${out}${err}")
message("${line}")
