# The front-page check must fail on a README whose figure has drifted from the run: the spinning-ball
# model's claim count, and a model's audit link, each changed in a copy.
#   cmake -D CHECK="python3;check_front_page.py;--derive;BIN" -D README=README.md -D WORK=DIR -P front_page_drifted.cmake
file(READ ${README} text)
foreach(edit "derives ([0-9]+) more;derives 5\\1 more" "generated/shot/AUDIT.md;generated/shots/AUDIT.md")
  list(GET edit 0 from)
  list(GET edit 1 to)
  string(REGEX REPLACE "${from}" "${to}" drifted "${text}")
  if(drifted STREQUAL text)
    message(FATAL_ERROR "README.md holds no `${from}` to change")
  endif()
  file(WRITE ${WORK}/README.md "${drifted}")
  execute_process(COMMAND ${CHECK} --readme ${WORK}/README.md RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 1 OR NOT out MATCHES "difference")
    message(FATAL_ERROR "the check passed a README with `${from}` changed (exit ${code}):\n${out}${err}")
  endif()
  message(STATUS "caught: ${from} → ${to}")
endforeach()
