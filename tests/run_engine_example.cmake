# The Open Dynamics Engine's free body (examples/engines/ode_free_body.cpp, which links ODE by its own
# `// geomech: pkg ode` line) checked in one mode, then each finding confirmed by the test's own
# computation (tests/engines/ode_confirm.cpp), so that no finding on a real engine rests on the suite alone.
#   cmake -DGEOMECH=... -DCONFIRM=ode_confirm -DFILE=ode_free_body.cpp -DMODE=trusted|untrusted|class
#         -DOUT=dir -P run_engine_example.cmake
if(NOT CONFIRM)
  message(FATAL_ERROR "libode-dev (and pkg-config) are not installed, so ODE cannot be checked: apt-get install -y "
                      "libode-dev pkg-config (./geomech installs them)")
endif()
set(props -p integrator_order -p integrator_unit_quaternion -p integrator_energy -p integrator_casimir -p integrator_noether)
# Trusted: compiled for every scalar, as `./geomech check ode_free_body.cpp` does (the three objects
# are linked together); the steps state double, so nothing runs in 50 digits. Sandboxed: double only.
if(NOT MODE STREQUAL "trusted")
  list(PREPEND props --scalar double)
endif()
file(REMOVE_RECURSE ${OUT})
get_filename_component(name ${FILE} NAME_WE)
if(MODE STREQUAL "class")
  file(MAKE_DIRECTORY ${OUT}/class)
  file(COPY ${FILE} DESTINATION ${OUT}/class)
  execute_process(COMMAND ${GEOMECH} check-class ${OUT}/class --report ${OUT}/report --parallel 1 --quiet ${props}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(dir ${OUT}/report/${name})
else()
  set(extra "")
  if(MODE STREQUAL "untrusted")
    set(extra --untrusted)
  endif()
  # --pkg ode on the command line as well as in the file: its flags count once, and every replay
  # command printed carries it (checked below).
  execute_process(COMMAND ${GEOMECH} check ${FILE} ${extra} --pkg ode --quiet --report ${OUT}/report ${props}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(dir ${OUT}/report)
endif()
message("${out}")
# Nothing is claimed (ODE's documentation claims nothing the suite can verify), so no claim can be
# false; but the order is asked of every step (it must converge to the notes' motion), and
# with the gyroscopic term off ODE's steps do not: those two rows FAIL, and nothing else.
if(NOT status EQUAL 1)
  message(FATAL_ERROR "exit status ${status}, expected 1 (the gyroscopic-off steps do not converge)\n${err}")
endif()
file(READ ${dir}/report.md report)
foreach(text "State: a unit quaternion q = (w, x, y, z) and the spatial angular velocity omega"
             "Precision: computes in double (stated: ODE is built in double here"
             "### dWorldStep_gyroscopic_off"
             " does not hold, 2 FAIL"
             "- **FAIL** `integrator_order [dWorldQuickStep_gyroscopic_off]`"
             "- **FAIL** `integrator_order [dWorldStep_gyroscopic_off]`"
             "| order | no | **DOES NOT CONVERGE** |"
             "the gyroscopic term (I Omega) x Omega is missing")
  string(FIND "${report}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the report (${dir}/report.md) does not contain: ${text}")
  endif()
endforeach()
# Every replay command carries the build options: each failing row's, run, fails again.
if(NOT MODE STREQUAL "class")
  set(REPLAY_VERDICTS ${dir}/verdicts.json)
  set(REPLAY_GEOMECH ${GEOMECH})
  set(REPLAY_MUST_CARRY "--pkg ode")
  include(${CMAKE_CURRENT_LIST_DIR}/replay_failures.cmake)
endif()
execute_process(COMMAND ${CONFIRM} ${dir}/verdicts.json RESULT_VARIABLE confirmed OUTPUT_VARIABLE said ERROR_VARIABLE said_err)
message("${said}${said_err}")
if(NOT confirmed EQUAL 0)
  message(FATAL_ERROR "the suite's findings on ODE and this test's own computation disagree (above)")
endif()
