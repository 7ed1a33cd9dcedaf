# ctest (issue 34): examples/hostile/peek_environ.py reads /proc/*/environ and /proc/*/cmdline and
# raises what it found. The test's environment holds GEOMECH_TEST_CANARY (ctest's ENVIRONMENT);
# checked untrusted, the canary must not reach the report, while the submission did run (its
# RuntimeError is there). With -DCONTROL=ON the same file is checked in-process, where the canary
# must be found: proof that the test can fail.
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
if(CONTROL)
  if(leaked EQUAL -1)
    message(FATAL_ERROR "control: in-process the submission did not find the canary; the untrusted test proves nothing")
  endif()
  message(STATUS "control, in-process: the canary reached the report, as expected without a sandbox")
else()
  if(NOT leaked EQUAL -1)
    message(FATAL_ERROR "the harness's environment reached the report through /proc:\n${report}")
  endif()
  message(STATUS "untrusted: the submission ran, read what /proc showed it, and found no canary")
endif()
