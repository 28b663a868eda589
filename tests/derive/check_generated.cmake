# The drift test: a fresh run of billiards-derive must equal the checked-in generated/, file for file
# and byte for byte, in both directions.
include(${CMAKE_CURRENT_LIST_DIR}/compare_trees.cmake)
run_derive(${DERIVE} ${WORK}/fresh)
compare_trees(${GENERATED} ${WORK}/fresh problems)
if(problems)
  message(FATAL_ERROR "generated/ is stale:\n${problems}"
                      "Regenerate it: ./build/derive/billiards-derive --out generated (see docs/code_generation.md).")
endif()
