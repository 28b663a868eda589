# bench/report.py given a file that is not FastFiz's bench_break JSON as --fastfiz (here
# CMakePresets.json, JSON of another shape) stops with one line naming the argument, the file and what
# was expected, exit status 2, and writes nothing. PYTHON, REPORT (bench/report.py), BENCH
# (billiards_bench), NOT_FASTFIZ (the file), WORK (a scratch folder).
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${BENCH} "--benchmark_filter=^collide/generated/double" --benchmark_min_time=0.001
                        --benchmark_format=json --benchmark_out=${WORK}/run.json
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "billiards_bench: exit status ${code}\n${err}")
endif()
execute_process(COMMAND ${PYTHON} ${REPORT} ${WORK}/run.json --fastfiz ${NOT_FASTFIZ} --out-dir ${WORK}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(STRIP "${err}" err)
if(NOT code EQUAL 2 OR NOT err MATCHES "^[^\n]*--fastfiz '[^']*CMakePresets.json': expected the JSON of FastFiz's bench_break[^\n]*$")
  message(FATAL_ERROR "report.py took a foreign --fastfiz file (exit ${code}):\n${out}${err}")
endif()
if(EXISTS ${WORK}/RESULTS.md)
  message(FATAL_ERROR "report.py wrote RESULTS.md from a run whose --fastfiz file it refused")
endif()
