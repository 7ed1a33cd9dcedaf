# The user's interpreter: `geomech check mine.py` runs the python3 first on PATH, not
# Debian's, when GEOMECH_PYTHON does not say otherwise. A venv made from Debian's Python (with its
# packages: --system-site-packages) is put first on PATH, GEOMECH_PYTHON is unset, and the report
# must name the venv's interpreter; in untrusted mode the sandbox must show the venv (read-only). The
# negative control: a venv without the system's packages has no mpmath, and the report says so,
# naming that interpreter and GEOMECH_PYTHON.
# no_gmpy2: mpmath on its pure-Python backend (MPMATH_NOGMPY): the report names the interpreter, the
# cost and the command that fixes it; the control, mode path (gmpy2 installed), says nothing of it.
#   cmake -DGEOMECH=... -DFILE=a.py -DOUT=dir -DMODE=path|untrusted|no_mpmath|no_gmpy2 -P run_interpreter_on_path.cmake
file(REMOVE_RECURSE ${OUT})
# A folder the sandbox's user can read (mkdtemp's 0700 would hide it from `nobody`).
file(MAKE_DIRECTORY ${OUT})
file(CHMOD ${OUT} DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
set(site --system-site-packages)
if(MODE STREQUAL "no_mpmath")
  set(site "")
endif()
execute_process(COMMAND /usr/bin/python3 -m venv --without-pip ${site} ${OUT}/venv RESULT_VARIABLE made ERROR_VARIABLE why)
if(NOT made EQUAL 0)
  message(FATAL_ERROR "cannot make a venv with /usr/bin/python3: ${why}")
endif()
unset(ENV{GEOMECH_PYTHON})
if(MODE STREQUAL "no_gmpy2")
  set(ENV{MPMATH_NOGMPY} 1)
endif()
set(ENV{PATH} "${OUT}/venv/bin:$ENV{PATH}")
set(extra --scalar double -p integrator_unit_quaternion)
set(status_wanted 0)
if(MODE STREQUAL "untrusted")
  list(APPEND extra --untrusted)
elseif(MODE STREQUAL "no_mpmath")
  set(extra -p integrator_unit_quaternion)
endif()
if(MODE STREQUAL "no_mpmath")
  # A file that imports mpmath itself cannot start: the message names the interpreter and GEOMECH_PYTHON.
  execute_process(COMMAND ${GEOMECH} check ${IMPORTS_MPMATH} --quiet --report ${OUT}/imports ${extra}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  foreach(text "No module named 'mpmath'" "the interpreter running it is ${OUT}/venv/bin/python3"
               "set GEOMECH_PYTHON to an interpreter that has it")
    string(FIND "${out}${err}" "${text}" at)
    if(at EQUAL -1 OR NOT status EQUAL 2)
      message(FATAL_ERROR "status ${status} (2 expected); the message does not say: ${text}")
    endif()
  endforeach()
endif()
execute_process(COMMAND ${GEOMECH} check ${FILE} --quiet --report ${OUT}/report ${extra}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
file(READ ${OUT}/report/report.md report)
set(wanted "Interpreter: ${OUT}/venv/bin/python3 (Python 3.")
if(MODE STREQUAL "no_mpmath")
  list(APPEND wanted "mpmath cannot be imported by ${OUT}/venv/bin/python3" "set GEOMECH_PYTHON to an interpreter that has it")
else()
  if(MODE STREQUAL "no_gmpy2")
    list(APPEND wanted "mpmath in ${OUT}/venv/bin/python3" "runs without gmpy2" "apt-get install python3-gmpy2")
  else()
    string(FIND "${report}" "without gmpy2" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "gmpy2 is installed, yet the report says mpmath runs without it")
    endif()
  endif()
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "exit status ${status}, expected 0")
  endif()
  list(APPEND wanted "**Result: PASS**")
endif()
foreach(text IN LISTS wanted)
  string(FIND "${report}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the report (${OUT}/report/report.md) does not contain: ${text}")
  endif()
endforeach()
