# Runs PROGRAM and requires it to stop with a failure (an assert aborts) whose output matches MESSAGE.
execute_process(COMMAND ${PROGRAM} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(result EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} finished normally; expected an assert to stop it:\n${out}${err}")
endif()
if(NOT "${out}${err}" MATCHES "${MESSAGE}")
  message(FATAL_ERROR "${PROGRAM} stopped (${result}) without the expected message '${MESSAGE}':\n${out}${err}")
endif()
