# One Python or Octave example checked end to end: `geomech check FILE --quiet` (plus ARGS), its exit
# status, and literal lines its report must contain (its own reason for failing, the function named).
#   cmake -DGEOMECH=... -DFILE=... -DSTATUS=0|1 -DEXPECT="text 1|text 2" -DNEED=python3|octave-cli
#         -DOUT=dir [-DARGS="--seed 7"] [-DREPLAY=ON] [-DABSENT="text|text"] -P run_remote_example.cmake
# EXPECT holds literal strings separated by '|', each looked for in report.md (no regex: the texts
# are the report's own words, brackets and all). A missing interpreter fails the test, naming the
# Debian package: the project's front door (./geomech) installs it, so its absence is a broken set-up,
# not a reason to skip.
find_program(INTERPRETER ${NEED})
if(NOT INTERPRETER)
  if(NEED STREQUAL "octave-cli")
    set(package octave)
  elseif(NEED STREQUAL "node")
    set(package nodejs)
  else()
    set(package ${NEED})
  endif()
  message(FATAL_ERROR "${NEED} is not installed, so ${FILE} cannot be checked: apt-get install -y ${package} "
                      "(./geomech installs it)")
endif()
file(REMOVE_RECURSE ${OUT})
separate_arguments(extra UNIX_COMMAND "${ARGS}")
execute_process(COMMAND ${GEOMECH} check ${FILE} --quiet --report ${OUT} ${extra}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT status STREQUAL STATUS)
  message(FATAL_ERROR "exit status ${status}, expected ${STATUS}\n${err}")
endif()
if(NOT EXISTS ${OUT}/report.md)
  message(FATAL_ERROR "no report was written in ${OUT}\n${err}")
endif()
file(READ ${OUT}/report.md report)
# -DINERT=ON: nothing the submission wrote may reach the report as a control character.
if(INERT)
  string(ASCII 27 esc)
  string(FIND "${report}" "${esc}" raw)
  if(NOT raw EQUAL -1)
    message(FATAL_ERROR "the report (${OUT}/report.md) holds a raw escape character from the submission")
  endif()
endif()
string(REPLACE "|" ";" wanted "${EXPECT}")
foreach(text IN LISTS wanted)
  string(FIND "${report}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the report (${OUT}/report.md) does not contain: ${text}\n${err}")
  endif()
endforeach()
# -DABSENT="text 1|text 2": literal strings report.md must not contain (a control of EXPECT's).
if(ABSENT)
  string(REPLACE "|" ";" unwanted "${ABSENT}")
  foreach(text IN LISTS unwanted)
    string(FIND "${report}" "${text}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "the report (${OUT}/report.md) contains, and must not: ${text}\n${err}")
    endif()
  endforeach()
endif()
# -DREPLAY=ON: every replay command printed for a failing row, run, fails again the same way.
if(REPLAY)
  set(REPLAY_VERDICTS ${OUT}/verdicts.json)
  set(REPLAY_GEOMECH ${GEOMECH})
  include(${CMAKE_CURRENT_LIST_DIR}/replay_failures.cmake)
endif()
