# billiards-spin-figures agrees with the closed forms (exit 0), finds the 30° rule's maximum, and the
# figures checked in beside it are what it draws now: a change to the runtime, the curves or the plot
# that alters a figure fails here until the figures are redrawn. PROGRAM, WORK (a scratch folder),
# FIGURES (the checked-in folder, docs/figures/).
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${PROGRAM} --out ${WORK} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "billiards-spin-figures: exit status ${code}\n${out}${err}")
endif()
if(NOT out MATCHES "maximum 33\\.75 degrees at a cut of 28\\.1 degrees")
  message(FATAL_ERROR "the 30-degree rule's maximum is not 33.75 degrees at 28.1 degrees:\n${out}")
endif()
foreach(figure IN ITEMS throw.svg thirty_degree_rule.svg)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/${figure} ${FIGURES}/${figure}
                  RESULT_VARIABLE different)
  if(different)
    message(FATAL_ERROR "docs/figures/${figure} is not what billiards-spin-figures draws now; redraw with "
                        "billiards-spin-figures --out docs/figures")
  endif()
endforeach()
file(GLOB leftovers ${WORK}/.*.tmp-*)
if(leftovers)
  message(FATAL_ERROR "temporary files left behind: ${leftovers}")
endif()
