# docs/audit_html.py writes its page and copies each figure beside it atomically: never through a link
# planted at either name (the link is replaced, its target left alone), with no temporary file left
# behind. PYTHON, SCRIPT (docs/audit_html.py), WORK (a scratch folder).
include(${CMAKE_CURRENT_LIST_DIR}/../planted_links.cmake)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/in ${WORK}/out)
file(WRITE ${WORK}/in/AUDIT.md "# An audit\n\n## Summary\n\n| claim | status |\n|---|---|\n| `a.b` | verified |\n\n## Steps\n\nText with $x^2$.\n")
set(figure "<svg xmlns=\"http://www.w3.org/2000/svg\"/>\n")
file(WRITE ${WORK}/in/figure.svg "${figure}")
plant_links(${WORK}/victim ${WORK}/out/page.html ${WORK}/out/figure.svg)
execute_process(COMMAND ${PYTHON} ${SCRIPT} --markdown ${WORK}/in/AUDIT.md --out ${WORK}/out/page.html
                        "--figure" "Steps=${WORK}/in/figure.svg|A figure"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "audit_html.py: exit status ${code}\n${out}${err}")
endif()
expect_links_replaced(${WORK}/victim ${WORK}/out/page.html ${WORK}/out/figure.svg)
file(READ ${WORK}/out/page.html page)
string(FIND "${page}" "<img src=\"figure.svg\"" position)
file(READ ${WORK}/out/figure.svg copied)
if(position EQUAL -1 OR NOT copied STREQUAL figure)
  message(FATAL_ERROR "page.html does not show the figure, or figure.svg is not its copy")
endif()
