# The drift comparison must catch a one-byte change, a missing file and an extra file.
include(${CMAKE_CURRENT_LIST_DIR}/compare_trees.cmake)
run_derive(${DERIVE} ${WORK}/fresh)
run_derive(${DERIVE} ${WORK}/copy)

compare_trees(${WORK}/fresh ${WORK}/copy problems)
if(problems)
  message(FATAL_ERROR "two fresh runs differ:\n${problems}")
endif()

# One byte changed: the last byte of audit.json, a newline, becomes a space.
file(READ ${WORK}/copy/audit.json contents)
string(REGEX REPLACE "\n$" " " contents "${contents}")
file(WRITE ${WORK}/copy/audit.json "${contents}")
compare_trees(${WORK}/fresh ${WORK}/copy problems)
if(NOT problems MATCHES "differs: audit.json")
  message(FATAL_ERROR "a one-byte change went unnoticed: '${problems}'")
endif()

run_derive(${DERIVE} ${WORK}/copy)
file(REMOVE ${WORK}/copy/AUDIT.md)
compare_trees(${WORK}/fresh ${WORK}/copy problems)
if(NOT problems MATCHES "missing from the fresh run: AUDIT.md")
  message(FATAL_ERROR "a missing file went unnoticed: '${problems}'")
endif()

run_derive(${DERIVE} ${WORK}/copy)
file(WRITE ${WORK}/copy/extra.hpp "")
compare_trees(${WORK}/fresh ${WORK}/copy problems)
if(NOT problems MATCHES "not checked in: extra.hpp")
  message(FATAL_ERROR "an extra file went unnoticed: '${problems}'")
endif()
