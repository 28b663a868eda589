# The length check must fail on a function of 151 lines (and pass one of 150, and a long `if`), and
# with --most-class 400 on a class of 401 lines (and pass one of 400).
#   cmake -D CHECK="python3;check_function_lengths.py" -D WORK=DIR -P long_function.cmake
# Writes HEAD, then lines made of LINE (its "@" the line's number) until the body from HEAD's "{" to
# the closing "}" spans `lines` lines, then CLOSE.
function(write_body path head line close lines)
  set(text "${head}\n")
  math(EXPR body "${lines} - 2")
  foreach(i RANGE 1 ${body})
    string(REPLACE "@" "${i}" numbered "${line}")
    string(APPEND text "${numbered}\n")
  endforeach()
  string(APPEND text "${close}\n")
  file(WRITE ${path} "${text}")
endfunction()
function(write_function path lines)
  write_body(${path} "int f(int x) {"
             "  x += @;  // \"{\" in a comment and '}' in a string are not braces: \"}\"" "}" ${lines})
endfunction()
write_function(${WORK}/long.cpp 151)
write_function(${WORK}/fits.cpp 150)
execute_process(COMMAND ${CHECK} --most 150 ${WORK}/long.cpp RESULT_VARIABLE code OUTPUT_VARIABLE out)
if(NOT code EQUAL 1 OR NOT out MATCHES "long.cpp:1: a function of 151 lines")
  message(FATAL_ERROR "the check passed a function of 151 lines (exit ${code}):\n${out}")
endif()
execute_process(COMMAND ${CHECK} --most 150 ${WORK}/fits.cpp RESULT_VARIABLE code OUTPUT_VARIABLE out)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the check refused a function of 150 lines (exit ${code}):\n${out}")
endif()

function(write_class path lines)
  write_body(${path} "template <int D>\nclass Engine : public Base<D> {" "  int member_@ = @;" "};" ${lines})
endfunction()
write_class(${WORK}/long_class.hpp 401)
write_class(${WORK}/fitting_class.hpp 400)
execute_process(COMMAND ${CHECK} --most 150 --most-class 400 ${WORK}/long_class.hpp RESULT_VARIABLE code
                OUTPUT_VARIABLE out)
if(NOT code EQUAL 1 OR NOT out MATCHES "long_class.hpp:2: a class of 401 lines")
  message(FATAL_ERROR "the check passed a class of 401 lines (exit ${code}):\n${out}")
endif()
execute_process(COMMAND ${CHECK} --most 150 --most-class 400 ${WORK}/fitting_class.hpp RESULT_VARIABLE code
                OUTPUT_VARIABLE out)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the check refused a class of 400 lines (exit ${code}):\n${out}")
endif()
