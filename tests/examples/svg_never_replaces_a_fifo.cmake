# billiards-table --svg FILE where FILE is a FIFO (as a device or a socket would be): the write is
# refused with one line and exit status 3, and the FIFO is left as it was. Renaming over it would have
# replaced it with the SVG, as `--svg /dev/full` once replaced that device when run as root.
# PROGRAM, WORK (a scratch folder).
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND mkfifo ${WORK}/pipe.svg RESULT_VARIABLE made)
if(NOT made EQUAL 0)
  message(FATAL_ERROR "mkfifo failed: ${made}")
endif()
execute_process(COMMAND ${PROGRAM} --collisions 5 --svg ${WORK}/pipe.svg RESULT_VARIABLE code
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 3 OR NOT err MATCHES "pipe.svg': it is not a regular file")
  message(FATAL_ERROR "--svg onto a FIFO: exit status ${code}, expected 3 and a refusal\n${err}")
endif()
execute_process(COMMAND test -p ${WORK}/pipe.svg RESULT_VARIABLE still_a_fifo)
if(NOT still_a_fifo EQUAL 0)
  message(FATAL_ERROR "pipe.svg is no longer a FIFO")
endif()
file(GLOB left ${WORK}/.pipe.svg.tmp-*)
if(left)
  message(FATAL_ERROR "temporary files left behind: ${left}")
endif()
