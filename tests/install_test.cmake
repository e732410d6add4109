# Installs the build to a fresh prefix and runs the installed program with no data folder chosen
# (no WOBBLE_* variables): it must find its problems, scenes and keys next to itself. A problem
# that exists only in the installed copy proves which folder it read.
#   cmake -DBUILD=<build dir> -DPREFIX=<empty prefix> -P install_test.cmake
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${PREFIX}"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
set(share "${PREFIX}/share/wobble")
foreach(folder problems scenes solutions)
  if(NOT IS_DIRECTORY "${share}/${folder}")
    message(FATAL_ERROR "${share}/${folder} was not installed")
  endif()
endforeach()
file(READ "${share}/problems/flying-plate.toml" text)
string(REPLACE "id = \"flying-plate\"" "id = \"installed-only\"" text "${text}")
file(WRITE "${share}/problems/installed-only.toml" "${text}")
set(clean ${CMAKE_COMMAND} -E env --unset=WOBBLE_PROBLEMS --unset=WOBBLE_SCENES
          --unset=WOBBLE_SOLUTIONS --unset=WOBBLE_DATA_DIR)
foreach(args "list" "solve;installed-only" "solve;flying-plate" "simulate;tennis-racket;--samples;3")
  execute_process(COMMAND ${clean} "${PREFIX}/bin/wobble" ${args}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "installed wobble ${args}: exit ${rc}\n${err}")
  endif()
endforeach()
# The module in lib/wobble, loaded by the installed program for a zip (a stand-in package: the
# export checks only that it is one).
if(NOT EXISTS "${PREFIX}/lib/wobble/wobble-on-demand.so")
  message(FATAL_ERROR "${PREFIX}/lib/wobble/wobble-on-demand.so was not installed")
endif()
file(WRITE "${PREFIX}/stand-in_1.0_amd64.deb" "!<arch>\ndebian-binary   ")
execute_process(COMMAND ${clean} "${PREFIX}/bin/wobble" export gradescope flying-plate
                        --deb "${PREFIX}/stand-in_1.0_amd64.deb" --out "${PREFIX}/autograder.zip"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS "${PREFIX}/autograder.zip")
  message(FATAL_ERROR "installed wobble export gradescope: exit ${rc}\n${err}")
endif()
message(STATUS "the installed program found its data in ${share} and its module")
