# Compiles SOURCE (collide_batch instantiated for double and float in 3-D) at -O3 to assembly and
# requires a prefetch instruction in the code of each instantiation: collide_batch asks memory for the
# next block beyond the caches (batch.hpp, detail::prefetch_next_block), and a compiler may drop such
# hints unseen (GCC 12 once deleted every one: a function whose only effect is a prefetch looked free of
# effects). CXX, INCLUDES (a ;-list of -I flags), SOURCE, OUT (the assembly file).
execute_process(COMMAND ${CXX} -std=c++20 -O3 ${INCLUDES} -S ${SOURCE} -o ${OUT}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the batch did not compile (${code}):\n${out}${err}")
endif()
file(READ ${OUT} assembly)
# An instantiation's code is its function and the functions of its lambdas (which a compiler may leave
# out of line), each from its label to its .size directive (GCC and clang alike). Mangled names:
# billiards::collide_batch<double, 3> is _ZN9billiards13collide_batchIdLm3EE…, its lambdas _ZZN9….
foreach(type_and_name d:double f:float)
  string(REPLACE ":" ";" type_and_name "${type_and_name}")
  list(GET type_and_name 0 type)
  list(GET type_and_name 1 scalar)
  string(REGEX MATCHALL "\n_ZZ?N9billiards13collide_batchI${type}Lm3EE[A-Za-z0-9_]*:" labels "${assembly}")
  if(NOT labels)
    message(FATAL_ERROR "no code for collide_batch<${scalar}, 3> in ${OUT}")
  endif()
  set(count 0)
  foreach(label IN LISTS labels)
    string(REGEX REPLACE "^\n(.*):$" "\\1" name "${label}")
    string(FIND "${assembly}" "${label}" begin)
    string(FIND "${assembly}" ".size\t${name}," end)
    if(end LESS begin)
      message(FATAL_ERROR "no .size directive after ${name} in ${OUT}")
    endif()
    math(EXPR length "${end} - ${begin}")
    string(SUBSTRING "${assembly}" ${begin} ${length} code_of)
    # x86's prefetcht0/prefetchw/prefetchnta, AArch64's prfm.
    string(REGEX MATCHALL "\n[ \t]*(prefetch[a-z0-9]*|prfm)[ \t]" found "${code_of}")
    list(LENGTH found found_count)
    math(EXPR count "${count} + ${found_count}")
  endforeach()
  if(count EQUAL 0)
    message(FATAL_ERROR "collide_batch<${scalar}, 3> has no prefetch instruction: its hints were dropped")
  endif()
  message("collide_batch<${scalar}, 3>: ${count} prefetch instructions")
endforeach()
