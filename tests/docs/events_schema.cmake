# billiards-shot's events JSON conforms to docs/events.schema.json, and the schema rejects each damaged
# copy of it. PROGRAM (billiards-shot), CHECK (the checker, a list), SCHEMA, WORK (a scratch folder).
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
foreach(shot IN ITEMS "--rack;9ball;--speed;8;--offset;0,0.25" "--table;7ft;--rack;8ball;--jitter;0.01;--seed;4;--speed;10")
  execute_process(COMMAND ${PROGRAM} ${shot} --json ${WORK}/events.json RESULT_VARIABLE code OUTPUT_QUIET
                  ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "billiards-shot ${shot}: exit status ${code}\n${err}")
  endif()
  foreach(mode IN ITEMS conforms rejects)
    set(extra)
    if(mode STREQUAL "rejects")
      set(extra --expect-rejected)
    endif()
    execute_process(COMMAND ${CHECK} --schema ${SCHEMA} --kind events ${extra} ${WORK}/events.json
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT code EQUAL 0)
      message(FATAL_ERROR "billiards-shot ${shot}: the schema check (${mode}) failed:\n${out}${err}")
    endif()
    message(STATUS "${out}")
  endforeach()
endforeach()
