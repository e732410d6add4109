# Writes help2man's include file for wobble.1: a COMMANDS section with each command's --help.
#   cmake -DWOBBLE=<program> -DOUT=<file> -P man_commands.cmake
set(text "[COMMANDS]\n")
foreach(cmd list solve check worksheet simulate bench keys serve page "export prairielearn" "export moodle"
            "export gradescope")
  separate_arguments(words UNIX_COMMAND "${cmd}")
  execute_process(COMMAND "${WOBBLE}" ${words} --help OUTPUT_VARIABLE help RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${WOBBLE} ${cmd} --help: exit ${rc}")
  endif()
  # roff: a backslash is written \e, and a line starting with a dot or quote is escaped.
  string(REPLACE "\\" "\\e" help "${help}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" help "${help}")
  string(APPEND text ".SS wobble ${cmd}\n.nf\n${help}.fi\n")
endforeach()
string(APPEND text "[FILES]\n.TP\nshare/wobble/problems, share/wobble/scenes, share/wobble/solutions\n"
       "The catalog, the example scenes and the golden keys, found next to the program; "
       "--data-dir or WOBBLE_DATA_DIR chooses others.\n")
file(WRITE "${OUT}" "${text}")
