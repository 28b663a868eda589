# A short run of billiards-gas as a user runs it: PROGRAM with ARGS (a ;-list) writes its JSON to
# WORK/gas.json; every field docs/simulations.md names must be there, with Z near the equation of state
# (EOS, within 3 %), the collision-rate identity within 5 errors, and energy, momentum and overlap kept.
file(MAKE_DIRECTORY ${WORK})
file(REMOVE ${WORK}/gas.json)
execute_process(COMMAND ${PROGRAM} ${ARGS} --json ${WORK}/gas.json RESULT_VARIABLE code OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "billiards-gas exited with ${code}:\n${out}${err}")
endif()
file(READ ${WORK}/gas.json json)
foreach(field dimension balls packing_fraction collisions time compressibility_factor mean_free_time temperature
              momentum largest_overlap events_per_second)
  string(JSON value ERROR_VARIABLE missing GET "${json}" ${field})
  if(missing)
    message(FATAL_ERROR "the JSON has no ${field}:\n${json}")
  endif()
  set(${field} ${value})
endforeach()
string(JSON z_error GET "${json}" compressibility_factor_error)
string(JSON z_rate GET "${json}" compressibility_factor_from_collision_rate)
string(JSON z_rate_error GET "${json}" compressibility_factor_from_collision_rate_error)
# CMake has no floating-point arithmetic: awk (in every Debian base system) does the comparisons.
foreach(value IN ITEMS "${compressibility_factor}" "${z_error}" "${z_rate}" "${z_rate_error}" "${temperature}"
              "${momentum}" "${largest_overlap}" "${events_per_second}" "${EOS}")
  if(NOT value MATCHES "^-?[0-9]+(\\.[0-9]+)?([eE][-+]?[0-9]+)?$")
    message(FATAL_ERROR "not a number: '${value}' in\n${json}")
  endif()
endforeach()
set(program "z=${compressibility_factor}\nze=${z_error}\nzr=${z_rate}\nzre=${z_rate_error}\neos=${EOS}\n")
string(APPEND program
       "d=z-eos\nif (d<0) d=-d\nif (d > 0.03*eos + 5*ze) { print \"Z is not within 3 % + 5 errors of the equation of state\"\nexit 1 }\n"
       "g=z-zr\nif (g<0) g=-g\nif (g > 5*(ze+zre)) { print \"the virial and the collision rate disagree\"\nexit 1 }\n"
       "t=${temperature}-1\nif (t<0) t=-t\nif (t >= 1e-12) { print \"the temperature changed\"\nexit 1 }\n"
       "if (${momentum} >= 1e-10) { print \"the momentum is not zero\"\nexit 1 }\n"
       "if (${largest_overlap} >= 1e-9) { print \"balls overlapped\"\nexit 1 }\n"
       "if (!(${events_per_second} > 0)) { print \"no events per second\"\nexit 1 }\n")
execute_process(COMMAND awk "BEGIN { ${program} }" RESULT_VARIABLE failed OUTPUT_VARIABLE why)
if(NOT failed EQUAL 0)
  message(FATAL_ERROR "${why}:\n${json}")
endif()
message("${json}")
