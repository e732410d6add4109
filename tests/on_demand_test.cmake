# The program loads cpp-httplib and libzip (and OpenSSL through them) only with its module:
# the program does not need them, the module does; and a program without its module says so
# in one line naming the file, with a non-zero exit and no file written, for the commands that
# need it, while every other command runs. The module needs no GiNaC or CLN of its own: it
# calls the program's (a second copy would keep registries of its own); and where the
# libraries every command loads are linked from their static archives (STATIC_DEPS), the
# program needs none of them: GiNaC, CLN, GMP, GSL, SUNDIALS, libedit.
#   cmake -DWOBBLE=<program> -DMODULE=<module> -DWORK=<empty folder> -DSTATIC_DEPS=<bool>
#         -P on_demand_test.cmake
function(needed file out)
  execute_process(COMMAND readelf -d "${file}" OUTPUT_VARIABLE dynamic RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "readelf -d ${file} failed")
  endif()
  string(REGEX MATCHALL "Shared library: \\[[^]]+\\]" libs "${dynamic}")
  list(TRANSFORM libs REPLACE "Shared library: \\[([^]]+)\\]" "\\1")
  set(${out} "${libs}" PARENT_SCOPE)
endfunction()
needed("${WOBBLE}" program_libs)
needed("${MODULE}" module_libs)
foreach(lib libcpp-httplib libzip libcrypto libssl)
  if(program_libs MATCHES "${lib}")
    message(FATAL_ERROR "the program needs ${lib}: ${program_libs}")
  endif()
endforeach()
foreach(lib libcpp-httplib libzip)
  if(NOT module_libs MATCHES "${lib}")
    message(FATAL_ERROR "the module does not need ${lib}: ${module_libs}")
  endif()
endforeach()
foreach(lib libginac libcln)
  if(module_libs MATCHES "${lib}")
    message(FATAL_ERROR "the module needs ${lib} (a second copy of it): ${module_libs}")
  endif()
endforeach()
foreach(lib libginac libcln libgmp libgsl libsundials libedit)
  if(STATIC_DEPS AND program_libs MATCHES "${lib}")
    message(FATAL_ERROR "the program needs ${lib}, not linked from its archive: ${program_libs}")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/bin")
file(COPY "${WOBBLE}" DESTINATION "${WORK}/bin")
get_filename_component(name "${WOBBLE}" NAME)
set(alone "${WORK}/bin/${name}")
file(WRITE "${WORK}/stand-in_1.0_amd64.deb" "!<arch>\ndebian-binary   ")
execute_process(COMMAND "${alone}" export gradescope flying-plate
                        --deb "${WORK}/stand-in_1.0_amd64.deb" --out "${WORK}/autograder.zip"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(STRIP "${err}" err)
if(rc EQUAL 0 OR NOT out STREQUAL "" OR EXISTS "${WORK}/autograder.zip")
  message(FATAL_ERROR "without its module: exit ${rc}, stdout '${out}'")
endif()
string(FIND "${err}" "${WORK}/bin/wobble-on-demand.so" next_to_it)
string(FIND "${err}" "${WORK}/lib/wobble/wobble-on-demand.so" installed)
if(err MATCHES "\n" OR NOT err MATCHES "wobble-on-demand.so is missing" OR next_to_it LESS 0
   OR installed LESS 0)
  message(FATAL_ERROR "without its module, the error is not one line naming where it looked:\n${err}")
endif()
execute_process(COMMAND "${alone}" solve flying-plate RESULT_VARIABLE rc OUTPUT_QUIET
                ERROR_VARIABLE solve_err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "without its module, solve failed (${rc}): ${solve_err}")
endif()
message(STATUS "the program needs ${program_libs}, not cpp-httplib, libzip or OpenSSL; "
               "without its module it says: ${err}")
