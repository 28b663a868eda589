# bench/report.py turns one run's JSON into RESULTS.md and throughput.svg, and must write both
# atomically: never through a link planted at either name (the link is replaced, its target left
# alone), with no temporary file left behind. PYTHON, REPORT (bench/report.py), BENCH
# (billiards_bench), WORK (a scratch folder).
include(${CMAKE_CURRENT_LIST_DIR}/../tests/planted_links.cmake)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${BENCH} "--benchmark_filter=^collide/(generated|paper_formula)/double|^batch/double/100/"
                        --benchmark_min_time=0.001 --benchmark_format=json --benchmark_out=${WORK}/run.json
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "billiards_bench: exit status ${code}\n${err}")
endif()
plant_links(${WORK}/victim ${WORK}/RESULTS.md ${WORK}/throughput.svg)
execute_process(COMMAND ${PYTHON} ${REPORT} ${WORK}/run.json --out-dir ${WORK} RESULT_VARIABLE code
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "report.py: exit status ${code}\n${out}${err}")
endif()
expect_links_replaced(${WORK}/victim ${WORK}/RESULTS.md ${WORK}/throughput.svg)
file(READ ${WORK}/RESULTS.md results)
string(FIND "${results}" "# Benchmark results" position)
string(FIND "${results}" "| generated `collide`" row)
if(NOT position EQUAL 0 OR row EQUAL -1)
  message(FATAL_ERROR "RESULTS.md is not the report of the run (no collide row)")
endif()
file(READ ${WORK}/throughput.svg svg)
string(FIND "${svg}" "<svg xmlns" position)
if(NOT position EQUAL 0)
  message(FATAL_ERROR "throughput.svg is not the SVG")
endif()
