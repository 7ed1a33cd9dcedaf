# A class folder mixing C++, Python, an Octave file and an Octave folder of function files (issue
# 15): `geomech check-class` must give one summary table with a row and the right verdict for each.
#   cmake -DGEOMECH=... -DEXAMPLES=examples/students -DOUT=dir -P run_mixed_class.cmake
file(REMOVE_RECURSE ${OUT})
set(class ${OUT}/class)
file(MAKE_DIRECTORY ${class}/octave_folder)
# C++: the energy (3.4) without its 1/2; Python: correct hat, vee, euler_3_8 and h with numpy
# (double only); Octave: (2.10) with .* instead of the matrix product.
file(COPY ${EXAMPLES}/bug_energy_alone.cpp ${EXAMPLES}/numpy_double_only.py ${EXAMPLES}/bug_elementwise.m
     DESTINATION ${class})
# An Octave implementation as a folder of function files, one function each, as MATLAB wants them.
file(WRITE ${class}/octave_folder/hat.m "function m = hat(v)\n  m = [0, -v(3), v(2); v(3), 0, -v(1); -v(2), v(1), 0];\nend\n")
file(WRITE ${class}/octave_folder/vee.m "function v = vee(m)\n  v = [m(3, 2); m(1, 3); m(2, 1)];\nend\n")
execute_process(COMMAND ${GEOMECH} check-class ${class} --trusted --report ${OUT}/reports --scalar double
                        -p definition_hat -p definition_vee -p definition_hamiltonian_3_4
                        -p definition_reconstruction_2_10
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT status EQUAL 1)
  message(FATAL_ERROR "exit status ${status}, expected 1 (two implementations fail)\n${err}")
endif()
file(READ ${OUT}/reports/summary.md summary)
# One row per implementation, with its verdict: | name | ... | VERDICT |
foreach(row "bug_energy_alone:FAIL" "numpy_double_only:PASS" "bug_elementwise:FAIL" "octave_folder:PASS")
  string(REPLACE ":" ";" parts ${row})
  list(GET parts 0 name)
  list(GET parts 1 verdict)
  string(REGEX MATCH "\n\\| *`?${name}`? *\\|[^\n]*" line "${summary}")
  if(NOT line)
    message(FATAL_ERROR "summary.md has no row for ${name}:\n${summary}")
  endif()
  string(FIND "${line}" "${verdict}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the row of ${name} does not say ${verdict}: ${line}")
  endif()
endforeach()
