# One step of the packaging tests (STEP): install the build tree into a scratch prefix, or build and
# run a consumer of it (the README's C++ examples among them). SCRATCH: a folder of our own; CXX: the compiler; SOURCE, BUILD: billiards'.
set(prefix ${SCRATCH}/prefix)
set(tests ${SOURCE}/tests/package)

function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    string(REPLACE ";" " " command "${ARGV}")
    message(FATAL_ERROR "failed (${code}): ${command}\n${out}\n${err}")
  endif()
endfunction()

if(STEP STREQUAL "install")
  file(REMOVE_RECURSE ${prefix})
  run(${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix})
  foreach(f IN ITEMS share/cmake/billiards/billiardsConfig.cmake share/cmake/billiards/billiardsConfigVersion.cmake
                     share/cmake/billiards/billiardsTargets.cmake share/pkgconfig/billiards.pc
                     include/billiards/collision.hpp include/billiards/kernels.hpp include/billiards/version.hpp
                     include/billiards/spin.hpp include/billiards/cloth.hpp include/billiards/spin_kernels.hpp include/billiards/shot_kernels.hpp
                     include/billiards/kernel_support.hpp
                     include/billiards/simulation/table.hpp include/billiards/simulation/gas.hpp
                     include/billiards/simulation/shot.hpp include/billiards/simulation/core/event_calendar.hpp
                     include/billiards/simulation/core/errors.hpp include/billiards/simulation/shot/detection.hpp
                     include/billiards/io.hpp include/billiards/io/shot.hpp include/billiards/io/atomic_file.hpp)
    if(NOT EXISTS ${prefix}/${f})
      message(FATAL_ERROR "cmake --install did not write ${f}")
    endif()
  endforeach()
elseif(STEP STREQUAL "find_package")
  # A separate project with only the scratch prefix on its path.
  file(REMOVE_RECURSE ${SCRATCH}/find_package)
  run(${CMAKE_COMMAND} -S ${tests}/find_package_consumer -B ${SCRATCH}/find_package -DCMAKE_CXX_COMPILER=${CXX}
      -DCMAKE_PREFIX_PATH=${prefix})
  run(${CMAKE_COMMAND} --build ${SCRATCH}/find_package)
  run(${SCRATCH}/find_package/consumer)
elseif(STEP STREQUAL "add_subdirectory")
  file(REMOVE_RECURSE ${SCRATCH}/add_subdirectory)
  run(${CMAKE_COMMAND} -S ${tests}/add_subdirectory_consumer -B ${SCRATCH}/add_subdirectory
      -DCMAKE_CXX_COMPILER=${CXX} -DBILLIARDS_SOURCE_DIR=${SOURCE})
  run(${CMAKE_COMMAND} --build ${SCRATCH}/add_subdirectory)
  run(${SCRATCH}/add_subdirectory/consumer)
  # Pulled in as a subdirectory, billiards builds neither its derivation nor its tests.
  file(GLOB_RECURSE built LIST_DIRECTORIES false ${SCRATCH}/add_subdirectory/billiards/*billiards-derive
       ${SCRATCH}/add_subdirectory/billiards/*_tests)
  if(built)
    message(FATAL_ERROR "add_subdirectory built what it did not ask for: ${built}")
  endif()
elseif(STEP STREQUAL "pkg_config")
  set(ENV{PKG_CONFIG_PATH} ${prefix}/share/pkgconfig)
  execute_process(COMMAND pkg-config --cflags billiards RESULT_VARIABLE code OUTPUT_VARIABLE cflags
                  ERROR_VARIABLE err OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "pkg-config --cflags billiards failed: ${err}")
  endif()
  separate_arguments(cflags UNIX_COMMAND "${cflags}")
  file(MAKE_DIRECTORY ${SCRATCH}/pkg_config)
  run(${CXX} -std=c++20 ${cflags} ${tests}/consumer_main.cpp -o ${SCRATCH}/pkg_config/consumer)
  run(${SCRATCH}/pkg_config/consumer)
elseif(STEP STREQUAL "examples")
  # examples/ is a project of its own that finds the installed package, as a user's program would.
  file(REMOVE_RECURSE ${SCRATCH}/examples)
  # No build type (the compiler's defaults, unoptimised): what is checked is that the installed package
  # is found and the programs build, link and run; the main build compiles them optimised.
  run(${CMAKE_COMMAND} -S ${SOURCE}/examples -B ${SCRATCH}/examples -DCMAKE_CXX_COMPILER=${CXX}
      -DCMAKE_BUILD_TYPE= -DCMAKE_PREFIX_PATH=${prefix})
  cmake_host_system_information(RESULT processors QUERY NUMBER_OF_LOGICAL_CORES)
  run(${CMAKE_COMMAND} --build ${SCRATCH}/examples --parallel ${processors})
  run(${SCRATCH}/examples/billiards-own-engine)
  run(${SCRATCH}/examples/shot-files ${SCRATCH}/examples)
  run(${SCRATCH}/examples/gas-snapshot ${SCRATCH}/examples)
  run(${SCRATCH}/examples/table-events)
elseif(STEP STREQUAL "readme_examples")
  # The C++ examples of README.md, as a user copies them: every ```cpp block is extracted from the
  # README (not copied into the tests), built as a program of its own against the installed package
  # (find_package(billiards), billiards::simulation, which brings the runtime) and run.
  set(work ${SCRATCH}/readme_examples)
  file(READ ${SOURCE}/README.md readme)
  # Brackets and semicolons kept out of the list's way (an unbalanced '[' would join list elements).
  string(REPLACE "[" "@LB@" readme "${readme}")
  string(REPLACE "]" "@RB@" readme "${readme}")
  string(REPLACE ";" "@SC@" readme "${readme}")
  string(REPLACE "\n" ";" lines "${readme}")
  set(examples)
  set(in_block OFF)
  set(count 0)
  file(REMOVE_RECURSE ${work})
  file(MAKE_DIRECTORY ${work})
  foreach(line IN LISTS lines)
    if(in_block)
      if(line MATCHES "^```")
        set(in_block OFF)
        file(WRITE ${work}/readme_example_${count}.cpp "${code}")
        list(APPEND examples readme_example_${count})
      else()
        string(REPLACE "@LB@" "[" line "${line}")
        string(REPLACE "@RB@" "]" line "${line}")
        string(REPLACE "@SC@" ";" line "${line}")
        string(APPEND code "${line}\n")
      endif()
    elseif(line MATCHES "^```cpp")
      set(in_block ON)
      math(EXPR count "${count} + 1")
      set(code "// README.md, C++ example ${count}\n")
    endif()
  endforeach()
  if(count LESS 3)
    message(FATAL_ERROR "README.md: ${count} C++ examples found (```cpp blocks), expected at least 3")
  endif()
  set(project "cmake_minimum_required(VERSION 3.25)\nproject(readme_examples LANGUAGES CXX)\n")
  string(APPEND project "find_package(billiards 0.2 CONFIG REQUIRED)\n")
  foreach(example IN LISTS examples)
    string(APPEND project "add_executable(${example} ${example}.cpp)\n")
    string(APPEND project "target_link_libraries(${example} PRIVATE billiards::simulation)\n")
    string(APPEND project "target_compile_options(${example} PRIVATE -Wall -Wextra -Werror)\n")
  endforeach()
  file(WRITE ${work}/CMakeLists.txt "${project}")
  run(${CMAKE_COMMAND} -S ${work} -B ${work}/build -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_BUILD_TYPE=Release
      -DCMAKE_PREFIX_PATH=${prefix})
  cmake_host_system_information(RESULT processors QUERY NUMBER_OF_LOGICAL_CORES)
  run(${CMAKE_COMMAND} --build ${work}/build --parallel ${processors})
  foreach(example IN LISTS examples)
    run(${work}/build/${example})
  endforeach()
  message(STATUS "${count} README examples built against ${prefix} and ran")
else()
  message(FATAL_ERROR "unknown STEP '${STEP}'")
endif()
