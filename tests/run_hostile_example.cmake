# ctest: one hostile submission (examples/hostile) checked in untrusted mode.
#   cmake -DGEOMECH=<geomech> -DFILE=<file> -DSTATUS=<exit status> -DREGEX=<regex the report must match> [-DREGEX2=<another>]
#         -DSOURCE=<suite source dir> -DOUT=<scratch dir> [-DARGS=<check options, ;-separated>]
#         [-DCONTROL=ON -DEXPECT_FILES=<;-separated paths>] -P run_hostile_example.cmake
#   (with CONTROL, an empty STATUS means any exit status)
# Asserts the verdict (exit status, a line of the report) and that nothing outside the sandbox
# changed: no file appeared in the suite's golden/ or in the victim folder the submission aims at,
# and (when run as root, where submissions run as nobody) no process of the sandbox's user is left.
#
# CONTROL=ON is the negative control of that test: the same submission checked in-process, where
# nothing stands between it and the machine. Its copy is compiled from a scratch folder outside
# the source tree (/tmp/geomech-hostile-control, with a golden/ of its own and a work/ folder it
# runs in), so that an escape lands there and not in the suite. The control asserts that the attack
# worked: the report matches REGEX (a forged verdict was believed) and every EXPECT_FILES exists
# (an escape wrote it). An empty STATUS or REGEX asserts nothing of its own. If the control ever
# stops showing the attack, the untrusted test proves nothing.

# The folder the hostile examples aim at (escape.cpp names it).
set(victim /tmp/geomech-hostile-victim)

# Runs `geomech check` on `file` in the folder `dir` with the given options, then the test's ARGS;
# sets rc (its exit status) and all (its output and report.md) in the caller.
function(gm_check file dir)
  execute_process(COMMAND ${GEOMECH} check ${file} ${ARGN} --report ${OUT} --cache-dir ${OUT}-cache ${ARGS}
                  WORKING_DIRECTORY ${dir} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(text "${out}${err}")
  if(EXISTS ${OUT}/report.md)
    file(READ ${OUT}/report.md report)
    string(APPEND text "${report}")
  endif()
  set(rc "${code}" PARENT_SCOPE)
  set(all "${text}" PARENT_SCOPE)
endfunction()

if(CONTROL)
  set(scratch /tmp/geomech-hostile-control)
  file(REMOVE_RECURSE ${scratch} ${victim} ${OUT})
  file(MAKE_DIRECTORY ${scratch}/src ${scratch}/golden ${scratch}/work ${victim})
  get_filename_component(name ${FILE} NAME)
  configure_file(${FILE} ${scratch}/src/${name} COPYONLY)
  gm_check(${scratch}/src/${name} ${scratch}/work)
  if(NOT STATUS STREQUAL "" AND NOT rc STREQUAL "${STATUS}")
    message(FATAL_ERROR "control: expected exit status ${STATUS} in-process, got ${rc}:\n${all}")
  endif()
  if(NOT REGEX STREQUAL "" AND NOT all MATCHES "${REGEX}")
    message(FATAL_ERROR "control: in-process the attack did not show ('${REGEX}' not in the report):\n${all}")
  endif()
  foreach(f ${EXPECT_FILES})
    if(NOT EXISTS ${f})
      message(FATAL_ERROR "control: in-process the submission did not write ${f}:\n${all}")
    endif()
  endforeach()
  file(REMOVE_RECURSE ${scratch} ${victim})
  message(STATUS "control, in-process: exit ${rc} (expected: '${STATUS}'); the report matches: '${REGEX}'; "
                 "files written outside the submission's folder: '${EXPECT_FILES}'")
  return()
endif()

file(REMOVE_RECURSE ${victim} ${OUT})
file(MAKE_DIRECTORY ${victim})
# Writable by anyone: if the sandbox let the submission out, its write would land here.
file(CHMOD ${victim} DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_WRITE
     GROUP_EXECUTE WORLD_READ WORLD_WRITE WORLD_EXECUTE)
file(GLOB_RECURSE golden_before LIST_DIRECTORIES true ${SOURCE}/golden/*)
# This check's sandboxes carry a tag of their own (harness/isolation/sandbox.cpp): the leftovers judged
# below are this check's, not those of another sandboxed run of the same user on this machine.
string(RANDOM LENGTH 16 ALPHABET abcdefghijklmnopqrstuvwxyz0123456789 tag)
set(tag "hostile-${tag}")
set(ENV{GEOMECH_SANDBOX_TAG} "${tag}")
gm_check(${FILE} ${CMAKE_CURRENT_BINARY_DIR} --untrusted)
if(NOT rc STREQUAL "${STATUS}")
  message(FATAL_ERROR "expected exit status ${STATUS}, got ${rc}:\n${all}")
endif()
foreach(r "${REGEX}" "${REGEX2}")
  if(NOT r STREQUAL "" AND NOT all MATCHES "${r}")
    message(FATAL_ERROR "the report does not match '${r}':\n${all}")
  endif()
endforeach()
file(GLOB_RECURSE golden_after LIST_DIRECTORIES true ${SOURCE}/golden/*)
if(NOT golden_before STREQUAL golden_after)
  message(FATAL_ERROR "the suite's golden/ changed during the check")
endif()
file(GLOB victim_files ${victim}/*)
if(victim_files)
  message(FATAL_ERROR "the submission wrote outside its sandbox: ${victim_files}")
endif()
if(EXISTS ${OUT}/../pwned OR EXISTS ${SOURCE}/pwned)
  message(FATAL_ERROR "the submission wrote a file beside its report or in the source tree")
endif()
execute_process(COMMAND id -u OUTPUT_VARIABLE uid OUTPUT_STRIP_TRAILING_WHITESPACE)
if(uid STREQUAL "0")
  # The sandbox's PID namespace is torn down by the kernel after its first process is killed:
  # allow it 15 s.
  foreach(i RANGE 15)
    execute_process(COMMAND sh -c "for p in $(ps -u 65534 -o pid=); do tr '\\0' '\\n' < /proc/$p/environ 2>/dev/null | grep -qx 'GEOMECH_SANDBOX_TAG=${tag}' && ps -o pid=,args= -p $p; done; true"
                    OUTPUT_VARIABLE left OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(left STREQUAL "")
      break()
    endif()
    execute_process(COMMAND sleep 1)
  endforeach()
  if(NOT left STREQUAL "")
    message(FATAL_ERROR "processes of this check's sandbox (tag ${tag}) outlived the check:\n${left}")
  endif()
endif()
file(REMOVE_RECURSE ${victim})
message(STATUS "exit ${rc}; report matches '${REGEX}'; nothing outside the sandbox changed")
