# The Bullet Physics SDK's free body (examples/engines/bullet_free_body.cpp, which links Bullet by its own
# `// geomech: pkg bullet` line, Debian's float build) checked in one mode, then each finding confirmed
# by the test's own computation with Bullet called directly (tests/engines/bullet_confirm.cpp).
#   cmake -DGEOMECH=... -DCONFIRM=bullet_confirm -DFILE=bullet_free_body.cpp -DMODE=trusted|untrusted
#         -DOUT=dir -P run_bullet_example.cmake
if(NOT CONFIRM)
  message(FATAL_ERROR "libbullet-dev (and pkg-config) are not installed, so Bullet cannot be checked: apt-get install -y "
                      "libbullet-dev pkg-config (./geomech installs them)")
endif()
set(props --scalar double -p integrator_order -p integrator_unit_quaternion -p integrator_energy -p integrator_casimir
          -p integrator_noether -p integrator_converges_in_every_regime)
set(extra "")
if(MODE STREQUAL "untrusted")
  set(extra --untrusted)
endif()
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${GEOMECH} check ${FILE} ${extra} --quiet --report ${OUT}/report ${props}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
# Nothing is claimed (Bullet's headers claim nothing the suite can verify), but the order is asked of
# every step: with the gyroscopic term off it does not converge, and the others do not at a fast state.
if(NOT status EQUAL 1)
  message(FATAL_ERROR "exit status ${status}, expected 1 (steps that do not converge)\n${err}")
endif()
file(READ ${OUT}/report/report.md report)
foreach(text "State: a unit quaternion q = (x, y, z, w) and the spatial angular velocity omega"
             "Precision: computes in float (stated: Bullet is built in single precision"
             "judged at float's round-off, eps = 1.19e-07"
             "| order | no | **DOES NOT CONVERGE** |"
             "the gyroscopic term (I Omega) x Omega is missing"
             "a guard on h")
  string(FIND "${report}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the report (${OUT}/report/report.md) does not contain: ${text}")
  endif()
endforeach()
# A float engine judged at its own precision: no finding is judged at double's round-off.
string(FIND "${report}" "round-off budget 7.11e-11" at)
if(NOT at EQUAL -1)
  message(FATAL_ERROR "the report judges Bullet, a float build, at double's round-off")
endif()
execute_process(COMMAND ${CONFIRM} ${OUT}/report/verdicts.json RESULT_VARIABLE confirmed OUTPUT_VARIABLE said
                ERROR_VARIABLE said_err)
message("${said}${said_err}")
if(NOT confirmed EQUAL 0)
  message(FATAL_ERROR "the suite's findings on Bullet and this test's own computation disagree (above)")
endif()
