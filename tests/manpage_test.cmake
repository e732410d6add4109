# The man page exists (help2man is installed by scripts/setup) and names every command.
#   cmake -DPAGE=<build>/wobble.1 -P manpage_test.cmake
if(NOT EXISTS "${PAGE}")
  message(FATAL_ERROR "${PAGE} was not generated (is help2man installed? scripts/setup installs it)")
endif()
file(READ "${PAGE}" text)
foreach(word list solve check worksheet simulate bench keys "wobble serve" "wobble page" "wobble export prairielearn"
             "wobble export moodle" "wobble export gradescope" "rigid-body rotation"
             "wobble simulate" "--max-evaluations" "share/wobble/problems")
  string(FIND "${text}" "${word}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${PAGE} does not mention '${word}'")
  endif()
endforeach()
