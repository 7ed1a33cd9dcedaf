# ctest: `geomech check-class` checks in untrusted mode by default.
#   cmake -DGEOMECH=<geomech> -DSOURCE=<suite source dir> -DOUT=<scratch dir> -P run_untrusted_class.cmake
# A class of three: alice (correct), mallory (a wrong hat that forges a PASS verdict and exits)
# and carol (does not compile). The summary must show alice passing, mallory failing and carol not
# compiling, and the run must say it is sandboxed.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT}/class)
configure_file(${SOURCE}/examples/students/correct.cpp ${OUT}/class/alice.cpp COPYONLY)
configure_file(${SOURCE}/examples/students/correct.hpp ${OUT}/class/correct.hpp COPYONLY)
configure_file(${SOURCE}/examples/hostile/forged_verdict.cpp ${OUT}/class/mallory.cpp COPYONLY)
file(WRITE ${OUT}/class/carol.cpp "#include <geomech/student.hpp>\nstruct Carol { int hat( };\n")
# Run from OUT with relative folders, as a lecturer would type them.
# alice.cpp includes correct.hpp, beside it in the flat folder: a header shared with every C++
# submission only when the lecturer says so.
execute_process(COMMAND ${GEOMECH} check-class class --report reports --cache-dir cache --shared class/correct.hpp
                        --parallel 2 --scalar double --property hat_is_cross_product
                WORKING_DIRECTORY ${OUT}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "expected exit status 1, got ${rc}:\n${out}${err}")
endif()
if(NOT err MATCHES "untrusted mode: each sandboxed")
  message(FATAL_ERROR "check-class did not say it runs in untrusted mode:\n${err}")
endif()
file(READ ${OUT}/reports/summary.md summary)
# Literal rows (string(FIND), not a regex: in a regex '|' would be an alternation that an empty
# branch lets match anything).
foreach(row "| alice | PASS |" "| mallory | **FAIL** |" "| carol | **DOES NOT COMPILE** |")
  string(FIND "${summary}" "${row}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the summary has no row '${row}':\n${summary}")
  endif()
endforeach()
message(STATUS "check-class, untrusted by default:\n${summary}")
