# ctest: examples/hostile/peek_environ.py reads /proc/*/environ and /proc/*/cmdline and
# raises what it found. The test's environment holds GEOMECH_TEST_CANARY (ctest's ENVIRONMENT);
# checked untrusted, neither the canary nor the folder the submission lies in (a path of this
# machine, which the command lines of the harness and of bubblewrap name) may be in what it found,
# while the submission did run (its RuntimeError is there). With -DCONTROL=ON the same file is
# checked in-process, where both must be found: proof that the test can fail.
#   cmake -DGEOMECH=<geomech> -DFILE=<peek_environ.py> -DOUT=<dir> [-DCONTROL=ON] -P run_environ_probe.cmake
if(NOT DEFINED ENV{GEOMECH_TEST_CANARY})
  message(FATAL_ERROR "GEOMECH_TEST_CANARY is not set: the test has nothing to look for")
endif()
set(canary "$ENV{GEOMECH_TEST_CANARY}")
file(REMOVE_RECURSE ${OUT})
if(CONTROL)
  set(mode "")  # a .py file is checked unsandboxed by default: the control
else()
  set(mode --untrusted)
endif()
execute_process(COMMAND ${GEOMECH} check ${FILE} ${mode} --scalar double -p definition_casimir --report ${OUT}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT EXISTS ${OUT}/report.md)
  message(FATAL_ERROR "no report (exit ${rc}):\n${out}${err}")
endif()
file(READ ${OUT}/report.md report)
string(FIND "${report}" "what I could read of other processes" ran)
if(ran EQUAL -1)
  message(FATAL_ERROR "the submission's exception is not in the report, so it did not run as expected:\n${report}")
endif()
string(FIND "${report}${out}${err}" "${canary}" leaked)
# What the submission found: its exception's text (the harness itself names the file elsewhere).
string(REGEX MATCHALL "what I could read of other processes:[^\n]*" found "${report}")
get_filename_component(folder ${FILE} DIRECTORY)
string(FIND "${found}" "${folder}" path_seen)
if(CONTROL)
  if(leaked EQUAL -1 OR path_seen EQUAL -1)
    message(FATAL_ERROR "control: in-process the submission did not find the canary and the folder ${folder} "
                        "(canary ${leaked}, folder ${path_seen}); the untrusted test proves nothing")
  endif()
  message(STATUS "control, in-process: the canary and the folder reached the report, as expected without a sandbox")
else()
  if(NOT leaked EQUAL -1)
    message(FATAL_ERROR "the harness's environment reached the report through /proc:\n${report}")
  endif()
  if(NOT path_seen EQUAL -1)
    message(FATAL_ERROR "a command line inside the sandbox names the folder ${folder} of this machine:\n${found}")
  endif()
  message(STATUS "untrusted: the submission ran, read what /proc showed it, and found no canary and no path")
endif()
