# billiards-table --svg FILE must never write through a link: neither one planted at the old fixed
# temporary name FILE.tmp nor one at FILE itself (the link is replaced, its target left alone), and
# it leaves no temporary file behind. PROGRAM, WORK (a scratch folder).
include(${CMAKE_CURRENT_LIST_DIR}/../planted_links.cmake)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
plant_links(${WORK}/victim ${WORK}/out.svg.tmp ${WORK}/linked.svg)
foreach(target IN ITEMS out.svg linked.svg)
  execute_process(COMMAND ${PROGRAM} --break --collisions 5 --svg ${WORK}/${target} RESULT_VARIABLE code
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "--svg ${target}: exit status ${code}\n${out}${err}")
  endif()
endforeach()
expect_links_replaced(${WORK}/victim ${WORK}/linked.svg)
file(READ ${WORK}/out.svg svg)
string(FIND "${svg}" "<svg xmlns" position)
if(NOT position EQUAL 0)
  message(FATAL_ERROR "out.svg is not the SVG")
endif()
