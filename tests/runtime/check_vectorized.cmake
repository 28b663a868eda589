# Compiles SOURCE at -O3 with the compiler's vectorisation report and requires it to name the batch
# loop of billiards/batch.hpp. CXX, COMPILER_ID (GNU or Clang), INCLUDES (a ;-list of -I flags).
if(COMPILER_ID STREQUAL "GNU")
  set(report -fopt-info-vec-optimized)
  set(pattern "batch\\.hpp:[0-9]+:[0-9]+: optimized: loop vectorized")
else()
  set(report -Rpass=loop-vectorize)
  set(pattern "batch\\.hpp:[0-9]+:[0-9]+: remark: vectorized loop")
endif()
execute_process(COMMAND ${CXX} -std=c++20 -O3 ${report} ${INCLUDES} -c ${SOURCE} -o ${OUT}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the batch loop did not compile (${code}):\n${out}${err}")
endif()
if(NOT "${out}${err}" MATCHES "${pattern}")
  message(FATAL_ERROR "the vectorisation report does not name the batch loop:\n${out}${err}")
endif()
string(REGEX MATCH "${pattern}[^\n]*" line "${out}${err}")
message("${line}")
