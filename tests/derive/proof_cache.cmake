cmake_policy(VERSION 3.25)
# The proof cache (BILLIARDS_PROOF_CACHE): a run with it writes what a run without it writes; its
# answers are taken (an entry forged to "not proven" fails the run); an entry of another Gappa version or
# of another script is never taken, and is written anew.
#   cmake -D DERIVE=billiards-derive -D WORK=DIR -P proof_cache.cmake
include(${CMAKE_CURRENT_LIST_DIR}/compare_trees.cmake)
set(cache ${WORK}/cache)
file(REMOVE_RECURSE ${WORK})

# derive(OUT EXPECTED_CODE [CACHED]): billiards-derive --model shot into OUT, with the cache or without.
function(derive out expected_code cached)
  file(REMOVE_RECURSE ${out})
  if(cached)
    set(env BILLIARDS_PROOF_CACHE=${cache})
  else()
    set(env --unset=BILLIARDS_PROOF_CACHE)
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${env} ${DERIVE} --out ${out} --model shot
                  RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT code EQUAL expected_code)
    message(FATAL_ERROR "billiards-derive (cache: ${cached}) exited ${code}, expected ${expected_code}:\n${err}")
  endif()
endfunction()

function(same_as_uncached out what)
  compare_trees(${WORK}/uncached ${out} problems)
  if(problems)
    message(FATAL_ERROR "${what}: the outputs differ from a run without the cache:\n${problems}")
  endif()
endfunction()

# entries(VAR): the cache's files.
function(entries var)
  file(GLOB found ${cache}/*.gappa)
  list(LENGTH found n)
  if(n EQUAL 0)
    message(FATAL_ERROR "the cache ${cache} holds no entry")
  endif()
  set(${var} ${found} PARENT_SCOPE)
endfunction()

# forge(FROM TO...): in every entry, each FROM replaced by its TO (pairs), and the proven made unproven.
function(forge)
  entries(found)
  foreach(f IN LISTS found)
    file(READ ${f} text)
    string(REPLACE "\nstatus 0\n" "\nstatus 1\n" text "${text}")
    set(pairs ${ARGN})
    while(pairs)
      list(POP_FRONT pairs from to)
      string(REPLACE "${from}" "${to}" text "${text}")
    endwhile()
    file(WRITE ${f} "${text}")
  endforeach()
endfunction()

derive(${WORK}/uncached 0 FALSE)
derive(${WORK}/first 0 TRUE)
same_as_uncached(${WORK}/first "the run that filled the cache")
derive(${WORK}/second 0 TRUE)
same_as_uncached(${WORK}/second "the run from the cache")

# Taken: every proof forged to "not proven" fails the run.
forge()
derive(${WORK}/forged 1 TRUE)

# Never taken from another Gappa version, or for another script.
file(REMOVE_RECURSE ${cache})
derive(${WORK}/refilled 0 TRUE)
forge("\nGappa " "\nGappx ")
derive(${WORK}/other_version 0 TRUE)
same_as_uncached(${WORK}/other_version "entries of another Gappa version")
forge(" -> " " ->  ")
derive(${WORK}/other_script 0 TRUE)
same_as_uncached(${WORK}/other_script "entries of other scripts")
# ... and those entries are written anew, as this run would.
entries(found)
foreach(f IN LISTS found)
  file(READ ${f} text)
  if(text MATCHES "Gappx|->  ")
    message(FATAL_ERROR "${f} was not written anew:\n${text}")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
