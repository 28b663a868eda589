# Configures billiards twice in a scratch folder: first as if GiNaC were missing (pkg-config disabled),
# then with it. The default BILLIARDS_REGENERATE=OFF cached by the first must become ON in the second,
# with a status message; a value the user set (-DBILLIARDS_REGENERATE=OFF) must stay, and the
# configure must say the build uses the checked-in generated/. SOURCE, WORK, CXX.
function(configure folder)
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${WORK}/${folder} -DCMAKE_CXX_COMPILER=${CXX}
                          -DBILLIARDS_BUILD_TESTS=OFF -DBILLIARDS_BUILD_BENCHMARKS=OFF -DBILLIARDS_BUILD_EXAMPLES=OFF
                          ${ARGN}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "configure failed (${code}):\n${out}${err}")
  endif()
  file(STRINGS ${WORK}/${folder}/CMakeCache.txt value REGEX "^BILLIARDS_REGENERATE:BOOL=")
  set(output "${out}" PARENT_SCOPE)
  set(cached "${value}" PARENT_SCOPE)
endfunction()

# Fails unless the cache holds EXPECTED and the configure's output matches MESSAGE.
function(require expected message why)
  if(NOT cached STREQUAL "BILLIARDS_REGENERATE:BOOL=${expected}")
    message(FATAL_ERROR "${why}: ${cached}, expected ${expected}\n${output}")
  endif()
  if(NOT output MATCHES "${message}")
    message(FATAL_ERROR "${why}: no status message matching '${message}':\n${output}")
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK})
configure(defaulted -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=TRUE)
require(OFF "from the checked-in generated/" "without GiNaC")
configure(defaulted -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=FALSE)
require(ON "BILLIARDS_REGENERATE was OFF by default" "GiNaC found on the second configure")
configure(explicit -DBILLIARDS_REGENERATE=OFF)
configure(explicit)
require(OFF "GiNaC is found but BILLIARDS_REGENERATE is OFF: the build uses the checked-in"
        "the user's -DBILLIARDS_REGENERATE=OFF")
file(REMOVE_RECURSE ${WORK})
