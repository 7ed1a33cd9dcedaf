# The Gradescope and PrairieLearn autograders, run as their platform runs them: `geomech autograder PLATFORM` writes
# the autograder from examples/class/rubric.json; each submission of examples/class is put into a
# folder tree made like the platform's in a temporary root (Gradescope: /autograder/{source,
# submission,results}, the zip unpacked into source/; PrairieLearn: /grade/{serverFilesCourse,
# student,results}); the platform's script runs; its results.json is validated against the
# documented format (tests/autograder/validate_results.py, whose --self-test is the control) and
# its grade compared with the gradebook's for the same submission.
#   cmake -DGEOMECH=... -DSOURCE=<repo> -DOUT=dir -DPLATFORM=gradescope|prairielearn -P run_autograder.cmake
find_program(PYTHON3 python3 REQUIRED)
file(REMOVE_RECURSE ${OUT})
set(examples ${SOURCE}/examples/class)
# Narrowed, to keep the test cheap: every assigned slot's own check in double, and the order claim.
set(checks --scalar double -p definition_hat -p definition_vee -p definition_omega_3_5 -p definition_euler_3_8
           -p definition_hamiltonian_3_4 -p definition_casimir -p definition_reconstruction_2_10
           -p definition_spatial_momentum -p definition_manakov_M -p definition_manakov_Omega -p definition_manakov_2_34
           -p integrator_order)
foreach(bundle ag ag-hidden)
  set(rubric ${examples}/rubric.json)
  if(bundle STREQUAL "ag-hidden")
    set(rubric ${examples}/rubric-hidden.json)
  endif()
  execute_process(COMMAND ${GEOMECH} autograder ${PLATFORM} ${OUT}/${bundle} --rubric ${rubric} ${checks}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "geomech autograder ${PLATFORM} (${rubric}) failed (${status}):\n${out}${err}")
  endif()
  message("${out}")
endforeach()
set(bundle ag)

# Each submission: NAME, its files, the grade expected (of 20) and a text its results must hold.
function(grade name expect_score expect_text)
  set(root ${OUT}/root-${bundle}-${name})
  if(PLATFORM STREQUAL "gradescope")
    set(sub ${root}/autograder/submission)
    file(MAKE_DIRECTORY ${root}/autograder/source ${sub})
    # What Gradescope does: the zip's contents in source/, run_autograder from there.
    execute_process(COMMAND ${PYTHON3} -m zipfile -e ${OUT}/${bundle}.zip ${root}/autograder/source RESULT_VARIABLE unzip)
    if(NOT unzip EQUAL 0 OR NOT EXISTS ${root}/autograder/source/run_autograder OR NOT EXISTS ${root}/autograder/source/setup.sh)
      message(FATAL_ERROR "ag.zip does not hold run_autograder and setup.sh at its root")
    endif()
    # zipfile -e does not restore modes: Gradescope's harness runs it as an executable, so check the
    # zip kept it executable, then run it as a program.
    execute_process(COMMAND ${PYTHON3} -c "import zipfile,sys; i=zipfile.ZipFile(sys.argv[1]).getinfo('run_autograder'); sys.exit(0 if (i.external_attr >> 16) & 0o100 else 1)" ${OUT}/${bundle}.zip
                    RESULT_VARIABLE exec_bit)
    if(NOT exec_bit EQUAL 0)
      message(FATAL_ERROR "run_autograder is not executable in ag.zip")
    endif()
    file(CHMOD ${root}/autograder/source/run_autograder PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
    set(script ${root}/autograder/source/run_autograder)
    set(env GEOMECH_AUTOGRADER_ROOT=${root}/autograder)
    set(results ${root}/autograder/results/results.json)
  else()
    set(sub ${root}/grade/student)
    file(MAKE_DIRECTORY ${sub})
    file(COPY ${OUT}/${bundle}/serverFilesCourse DESTINATION ${root}/grade)
    set(script ${root}/grade/serverFilesCourse/geomech/run.sh)
    set(env GEOMECH_GRADER_ROOT=${root}/grade)
    set(results ${root}/grade/results/results.json)
  endif()
  foreach(f IN LISTS ARGN)
    if(IS_ABSOLUTE ${f})
      file(COPY ${f} DESTINATION ${sub})
    else()
      file(COPY ${examples}/submissions/${f} DESTINATION ${sub})
    endif()
  endforeach()
  # Its scratch folder in a TMPDIR of the test's own, which it must leave as it found it.
  set(tmp ${OUT}/tmp-${name})
  file(MAKE_DIRECTORY ${tmp})
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${env} GEOMECH=${GEOMECH} TMPDIR=${tmp} ${script}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  file(GLOB left ${tmp}/geomech-grade-*)
  if(left)
    message(FATAL_ERROR "${name}: grade-submission left its work folder behind: ${left}")
  endif()
  if(NOT EXISTS ${results})
    message(FATAL_ERROR "${name}: no results.json (status ${status}):\n${out}${err}")
  endif()
  execute_process(COMMAND ${PYTHON3} ${CMAKE_CURRENT_LIST_DIR}/autograder/validate_results.py ${PLATFORM} ${results}
                  RESULT_VARIABLE valid OUTPUT_VARIABLE vout)
  if(NOT valid EQUAL 0)
    message(FATAL_ERROR "${name}: results.json is not valid ${PLATFORM} results:\n${vout}")
  endif()
  file(READ ${results} json)
  # The instructor's log says the grade of the rubric (of 20), as results.json does: the inner check
  # ran with the rubric (before, its console said "87.50 of 100" beside a results.json of 38.46).
  if("${out}" MATCHES "[0-9]\\.[0-9][0-9] of 100")
    message(FATAL_ERROR "${name}: the instructor's log shows a grade of another rubric:\n${out}")
  endif()
  # A student reads no path of the grading machine.
  if("${json}" MATCHES "the compiler's full output: /")
    message(FATAL_ERROR "${name}: results.json shows the grader's log path:\n${json}")
  endif()
  if(PLATFORM STREQUAL "gradescope")
    string(JSON score GET "${json}" score)
  elseif(expect_score STREQUAL "not gradable")
    string(JSON gradable GET "${json}" gradable)
    if(NOT gradable STREQUAL "OFF")
      message(FATAL_ERROR "${name}: expected not gradable:\n${json}")
    endif()
    set(score "not gradable")
    # Not graded has no score: the message never says one ("0.00 of 20" was said).
    string(JSON said GET "${json}" message)
    if(said MATCHES "[0-9]+\\.[0-9][0-9] of [0-9]")
      message(FATAL_ERROR "${name}: a submission that is not gradable is given a score in its message: ${said}")
    endif()
  else()
    string(JSON fraction GET "${json}" score)
    # the fraction times 20, to 2 decimals
    execute_process(COMMAND ${PYTHON3} -c "print('%.2f' % (20 * ${fraction}))" OUTPUT_VARIABLE score OUTPUT_STRIP_TRAILING_WHITESPACE)
  endif()
  if(NOT score EQUAL expect_score AND NOT score STREQUAL expect_score)
    message(FATAL_ERROR "${name}: grade ${score}, expected ${expect_score}:\n${json}")
  endif()
  string(FIND "${json}" "${expect_text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${name}: results.json does not say: ${expect_text}\n${json}")
  endif()
  message(STATUS "${name}: ${PLATFORM} results valid, grade ${score}")
  set(results ${results} PARENT_SCOPE)
endfunction()

# alice: every assigned slot right, her order claim verified: full marks.
grade(alice 20 "PASS, 20.00 of 20" alice.py)
# bob: Manakov's Omega through numpy (fine in double, and this run is in double); no integrator, so
# no claim credit: 11 of 11 slots (weights 13) of 15 weights is 17.33 of 20, and INCOMPLETE.
grade(bob 17.33 "INCOMPLETE, 17.33 of 20" bob.py)
# dave, a folder of Octave function files: manakov_Omega (weight 1) wrong, and manakov_2_34
# (weight 2) failing through it: 10 of 15 weights, 13.33 of 20, the first fix the callee.
grade(dave 13.33 "first fix: Octave function 'manakov_Omega'" dave)
# nina, a Jupyter notebook with a Python kernel (examples/students/bug_week3.ipynb): its code cells
# are graded; of the assignment it writes hat, vee, omega_3_5, hamiltonian_3_4 and casimir right and
# euler_3_8 (weight 2) wrong: 5 of 15 weights, 6.67 of 20, the first fix naming the cell and line.
grade(nina 6.67 "Python function 'euler_3_8' in bug_week3.ipynb (cell 6, In [3], line 9) is wrong"
      ${SOURCE}/examples/students/bug_week3.ipynb)
if(PLATFORM STREQUAL "gradescope")
  grade(gina 0 "DOES NOT COMPILE" gina.cpp)
else()
  grade(gina "not gradable" "does not compile" gina.cpp)
endif()

# Hidden tests (examples/class/rubric-hidden.json): dave's wrong manakov_Omega and manakov_2_34 are
# shown after the due date (the order claim never, but dave makes no claim), and so is the whole
# report. Same grade; nothing a student sees now names them.
set(bundle ag-hidden)
grade(dave 13.33 "they count in the score" dave)
execute_process(COMMAND ${PYTHON3} -c [=[
import json, sys
platform, path = sys.argv[1:3]
r = json.load(open(path))
hidden = ("manakov_Omega", "manakov_2_34")
if platform == "gradescope":
    levels = {t["name"].split(":")[0]: t.get("visibility") for t in r["tests"]}
    want = {"slot manakov_Omega": "after_due_date", "slot manakov_2_34": "after_due_date",
            "the whole report (report.md)": "after_due_date"}
    wrong = ["%s is %s, expected %s" % (k, levels.get(k), v) for k, v in want.items() if levels.get(k) != v]
    shown = [r.get("output", "")] + [t.get("output", "") + t["name"] for t in r["tests"] if t.get("visibility") == "visible"]
else:
    wrong = ["the test %s is listed" % t["name"] for t in r["tests"] if t["name"] in hidden]
    shown = [json.dumps(r)]
wrong += ["a visible text names %s: %s" % (h, s[:300]) for s in shown for h in hidden if h in s]
print(chr(10).join(wrong))
sys.exit(1 if wrong else 0)
]=] ${PLATFORM} ${results} RESULT_VARIABLE leak OUTPUT_VARIABLE said)
if(NOT leak EQUAL 0)
  message(FATAL_ERROR "hidden tests are shown on ${PLATFORM} (${results}):\n${said}")
endif()
message(STATUS "${PLATFORM}: autograder written, five submissions graded (one a notebook), every results.json valid; hidden tests hidden")
