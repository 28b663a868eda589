# The worked example of docs/adding_a_model.md: its billiards-derive verifies every claim and proves its
# kernel, writes the audit and the header; the header compiles on its own and its kernel gives the
# distance v_0²/(2 μ_r g).
#   cmake -D DERIVE=billiards-derive-rolling -D WORK=DIR -D CXX=compiler -D SOURCE=tests/derive -P adding_a_model.cmake
file(REMOVE_RECURSE ${WORK})
execute_process(COMMAND ${DERIVE} --out ${WORK} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the example's derivation exited ${code}:\n${out}${err}")
endif()
if(NOT out MATCHES "claims: 3  verified: 3  failed: 0  assumptions: 0")
  message(FATAL_ERROR "the example's summary is not three claims verified:\n${out}")
endif()
foreach(file rolling/AUDIT.md rolling/audit.json rolling/rolling_kernels.hpp)
  if(NOT EXISTS ${WORK}/${file})
    message(FATAL_ERROR "the example wrote no ${file}")
  endif()
endforeach()
file(READ ${WORK}/rolling/AUDIT.md audit)
if(NOT audit MATCHES "stop_distance" OR NOT audit MATCHES "The prover's canaries")
  message(FATAL_ERROR "the example's audit names no kernel stop_distance or no canaries")
endif()
file(WRITE ${WORK}/call.cpp "#include <rolling/rolling_kernels.hpp>\n#include <cmath>\n#include <cstdio>\n"
  "int main() {\n"
  "  const double d = rolling::kernels::stop_distance(2.0, 1.0 / 64, 9.81);\n"
  "  const float f = rolling::kernels::stop_distance(2.0f, 1.0f / 64, 9.81f);\n"
  "  const double exact = 4.0 * 64 / (2 * 9.81);\n"
  "  std::printf(\"%.17g %.9g %.17g\\n\", d, static_cast<double>(f), exact);\n"
  "  return std::fabs(d - exact) <= 4e-16 * exact && std::fabs(f - exact) <= 4e-7 * exact ? 0 : 1;\n"
  "}\n")
execute_process(COMMAND ${CXX} -std=c++20 -Wall -Wextra -Werror -I ${WORK} ${WORK}/call.cpp -o ${WORK}/call
                RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the example's header does not compile:\n${err}")
endif()
execute_process(COMMAND ${WORK}/call RESULT_VARIABLE code OUTPUT_VARIABLE out)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the example's kernel is off v_0²/(2 μ_r g) (double, float, exact): ${out}")
endif()
message(STATUS "derived, proven and called: ${out}")
