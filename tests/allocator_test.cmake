# The program allocates with jemalloc, configured by the program itself (src/cli/allocator.cpp):
# jemalloc's statistics, asked for at exit, are printed at all (so jemalloc, not the C
# library's malloc, served the program) and show the options the program sets, huge pages for
# the heap and for jemalloc's own bookkeeping; the program's output is unchanged.
#   cmake -DWOBBLE=<program> -P allocator_test.cmake
execute_process(COMMAND ${CMAKE_COMMAND} -E env MALLOC_CONF=stats_print:true
                        "${WOBBLE}" solve flying-plate --part a
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "wobble solve exited ${rc}: ${err}")
endif()
if(NOT err MATCHES "Begin jemalloc statistics")
  message(FATAL_ERROR "no jemalloc statistics at exit: the program does not allocate with "
                      "jemalloc:\n${err}")
endif()
foreach(option thp metadata_thp)
  if(NOT err MATCHES "opt\\.${option}: \"always\"")
    string(REGEX MATCH "opt\\.${option}: [^\n]*" got "${err}")
    message(FATAL_ERROR "jemalloc's ${option} is not \"always\" (the program's option): ${got}")
  endif()
endforeach()
execute_process(COMMAND "${WOBBLE}" solve flying-plate --part a
                RESULT_VARIABLE rc OUTPUT_VARIABLE plain)
if(NOT out STREQUAL plain OR out STREQUAL "")
  message(FATAL_ERROR
          "the key differs with jemalloc's statistics asked for:\n${out}\n---\n${plain}")
endif()
message(STATUS "jemalloc serves the program with huge pages; the key is unchanged")
