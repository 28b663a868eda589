# Every Catch2 test case's name can be carried by catch_discover_tests into a ctest test of its own:
# no '[', ']' (Catch's tag brackets), ';' (a CMake list separator) or '\' in it. One such name folded
# every later test case of its binary into a single ctest entry (128 tests listed instead of 191), and
# nothing failed. Reads the test sources of tests/ (-D SOURCE=the project root).
file(GLOB_RECURSE sources ${SOURCE}/tests/*.cpp)
set(names 0)
# TEST_CASE("name", ...) and TEMPLATE_TEST_CASE("name", ...), the name possibly on the next line.
set(opening "TEST_CASE\\([ \t\r\n]*\"")
foreach(source IN LISTS sources)
  file(READ ${source} text)
  string(REGEX MATCH "${opening}[^\"]*[][;\\\\][^\"]*\"" offending "${text}")
  if(offending)
    string(REGEX REPLACE "^${opening}" "\"" offending "${offending}")
    file(RELATIVE_PATH where ${SOURCE} ${source})
    message(FATAL_ERROR "${where}: the test case ${offending} has a '[', ']', ';' or '\\' in its name, "
                        "which catch_discover_tests cannot carry into ctest; name it without them")
  endif()
  string(REGEX MATCHALL "${opening}" cases "${text}")
  list(LENGTH cases count)
  math(EXPR names "${names} + ${count}")
endforeach()
if(names EQUAL 0)
  message(FATAL_ERROR "no TEST_CASE found under ${SOURCE}/tests: the pattern no longer matches the sources")
endif()
message(STATUS "${names} test case names, each one ctest can carry")
