# One Python or Octave example checked end to end: `geomech check FILE --quiet` (plus ARGS), its exit
# status and a line of its report. Skipped (exit 77, ctest SKIP_RETURN_CODE) when the interpreter
# is missing, with a message saying which.
#   cmake -DGEOMECH=... -DFILE=... -DSTATUS=0|1 -DREGEX=... -DNEED=python3|octave-cli -DOUT=dir -P run_remote_example.cmake
find_program(INTERPRETER ${NEED})
if(NOT INTERPRETER)
  message("SKIPPED: ${NEED} is not installed (apt-get install -y ${NEED}); ${FILE} was not checked")
  cmake_language(EXIT 77)
endif()
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${GEOMECH} check ${FILE} --quiet --report ${OUT} ${ARGS}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT status STREQUAL STATUS)
  message(FATAL_ERROR "exit status ${status}, expected ${STATUS}\n${err}")
endif()
if(REGEX)
  file(READ ${OUT}/report.md report)
  if(NOT report MATCHES "${REGEX}")
    message(FATAL_ERROR "the report does not match '${REGEX}'\n${err}")
  endif()
endif()
