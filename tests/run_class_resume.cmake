# A lecturer's class run that nothing stops from finishing, in untrusted mode:
#  - the class lies in a private folder (mode 0700, as `mktemp -d` makes it); run as root (as CI
#    runs), the sandbox runs as nobody, who cannot enter it: every Python and Octave submission
#    must still be checked (each from a private read-only copy), with its verdict;
#  - a run stopped after one implementation by SIGINT (Ctrl-C), then after one more by SIGKILL (a
#    killed job), leaves a summary of what is done each time, and the next run resumes: it checks
#    only what was not finished and ends with the same summary.md as an uninterrupted run;
#  - a submission changed since is checked again; --fresh checks everyone (the control: the same
#    run without resuming says nothing was resumed);
#  - --grades writes the gradebook CSV.
#   cmake -DGEOMECH=... -DEXAMPLES=examples/students -DOUT=dir -P run_class_resume.cmake
file(REMOVE_RECURSE ${OUT})
set(class ${OUT}/private)
file(MAKE_DIRECTORY ${class}/octave_folder)
file(COPY ${EXAMPLES}/numpy_double_only.py ${EXAMPLES}/bug_elementwise.m DESTINATION ${class})
# A Python file whose vee (2.11) has one sign wrong.
file(WRITE ${class}/wrong_vee.py "def hat(v):\n    return [[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]]\n\n\n"
                                 "def vee(m):\n    return [m[2][1], m[0][2], -m[1][0]]\n")
file(WRITE ${class}/octave_folder/hat.m "function m = hat(v)\n  m = [0, -v(3), v(2); v(3), 0, -v(1); -v(2), v(1), 0];\nend\n")
file(WRITE ${class}/octave_folder/vee.m "function v = vee(m)\n  v = [m(3, 2); m(1, 3); m(2, 1)];\nend\n")
file(CHMOD ${class} DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
set(options --scalar double --parallel 1 -p definition_hat -p definition_vee -p definition_hamiltonian_3_4
            -p definition_reconstruction_2_10 -p definition_hat_n -p definition_vee_n)

function(run_class dir env expect_status)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${env} ${GEOMECH} check-class ${class} --report ${dir} ${options}
                          --grades ${dir}.csv ${ARGN}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(out "${out}${err}" PARENT_SCOPE)
  if(expect_status STREQUAL "signal")
    # (cmake -E env reports the child's death by a signal as status 1 and "User interrupt" or the
    # signal's name; what matters is what the stopped run left on disk, checked below)
    if(status EQUAL 0)
      message(FATAL_ERROR "${env}: the run should have been stopped by its signal, it ended with ${status}:\n${out}${err}")
    endif()
  elseif(NOT status MATCHES "^(${expect_status})$")
    message(FATAL_ERROR "exit status ${status}, expected ${expect_status}:\n${out}${err}")
  endif()
endfunction()

# The uninterrupted run.
run_class(${OUT}/full "GEOMECH_UNUSED=1" 1)
file(READ ${OUT}/full/summary.md full)
foreach(row "numpy_double_only:PASS" "wrong_vee:FAIL" "bug_elementwise:FAIL" "octave_folder:PASS")
  string(REPLACE ":" ";" parts ${row})
  list(GET parts 0 name)
  list(GET parts 1 verdict)
  string(REGEX MATCH "\n\\| *${name} *\\|[^\n]*" line "${full}")
  string(FIND "${line}" "${verdict}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the row of ${name} does not say ${verdict} (a private folder must not stop a check):\n${full}")
  endif()
endforeach()
string(FIND "${full}" "NOT CHECKED" not_checked)
if(NOT not_checked EQUAL -1)
  message(FATAL_ERROR "a submission in the private folder was not checked:\n${full}")
endif()
# The console gives each student a line as their check ends: result, grade, time.
if(NOT out MATCHES "\\[[1-4]/4\\] wrong_vee: FAIL, [0-9]+\\.[0-9][0-9] of 100, [0-9]+ s\n")
  message(FATAL_ERROR "no console line with wrong_vee's result, grade and time:\n${out}")
endif()
# Each student in words, with the first fix of the wrong one.
string(FIND "${full}" "- **wrong_vee** (Python): FAIL, " words)
string(FIND "${full}" "first fix: Python function 'vee' in wrong_vee.py is wrong" fix)
if(words EQUAL -1 OR fix EQUAL -1)
  message(FATAL_ERROR "the summary does not say in words what is wrong with wrong_vee:\n${full}")
endif()
# The gradebook: a header and one row per student, CRLF line ends.
file(STRINGS ${OUT}/full.csv grades)
list(LENGTH grades n)
list(GET grades 0 header)
if(NOT n EQUAL 5 OR NOT header MATCHES "^Implementation,Username,Email address,ID number,geomech,Feedback")
  message(FATAL_ERROR "the gradebook is not a header and 4 rows (${n} lines):\n${grades}")
endif()

# Stopped by SIGINT after one implementation, then by SIGKILL after one more.
run_class(${OUT}/stopped "GEOMECH_TEST_STOP_AFTER=1:INT" signal)
file(READ ${OUT}/stopped/summary.md partial)
if(NOT partial MATCHES "In progress: 1 of 4 implementations checked")
  message(FATAL_ERROR "after SIGINT the summary does not say what is done:\n${partial}")
endif()
# Ctrl-C says what was kept and the command that resumes (without --fresh), and the
# gradebook says what the summary says: the three not checked yet have no grade, and say why.
if(NOT out MATCHES "interrupted\\. 1 of 4 results are kept in [^\n]*The same command resumes, checking only those:\n  [^\n]*check-class")
  message(FATAL_ERROR "Ctrl-C did not say what was kept and how to resume:\n${out}")
endif()
function(expect_no_grade_rows csv count)
  file(READ ${csv} text)
  string(REGEX MATCHALL ",,\"?no grade yet: the class run stopped before checking this submission" rows "${text}")
  list(LENGTH rows n)
  if(NOT n EQUAL ${count})
    message(FATAL_ERROR "${csv}: ${n} rows without a grade, expected ${count} (as the summary lists):\n${text}")
  endif()
endfunction()
expect_no_grade_rows(${OUT}/stopped.csv 3)
run_class(${OUT}/stopped "GEOMECH_TEST_STOP_AFTER=1:KILL" signal)
if(NOT out MATCHES "1 of 4 implementations are unchanged")
  message(FATAL_ERROR "the run after SIGINT did not resume:\n${out}")
endif()
file(READ ${OUT}/stopped/summary.md partial)
if(NOT partial MATCHES "In progress: 2 of 4 implementations checked")
  message(FATAL_ERROR "after SIGKILL the summary does not say what is done:\n${partial}")
endif()
run_class(${OUT}/stopped "GEOMECH_UNUSED=1" 1)
if(NOT out MATCHES "2 of 4 implementations are unchanged")
  message(FATAL_ERROR "the run after SIGKILL did not resume:\n${out}")
endif()
file(READ ${OUT}/stopped/summary.md resumed)
if(NOT resumed STREQUAL full)
  message(FATAL_ERROR "the resumed run's summary differs from the uninterrupted one:\n${resumed}\n---\n${full}")
endif()
file(READ ${OUT}/stopped.csv resumed_grades)
file(READ ${OUT}/full.csv full_grades)
if(NOT resumed_grades STREQUAL full_grades)
  message(FATAL_ERROR "the resumed run's gradebook differs from the uninterrupted one")
endif()

# A changed submission is checked again; --fresh checks everyone.
file(APPEND ${class}/numpy_double_only.py "\n# changed after its check\n")
run_class(${OUT}/stopped "GEOMECH_UNUSED=1" 1)
if(NOT out MATCHES "3 of 4 implementations are unchanged")
  message(FATAL_ERROR "a changed submission was not checked again:\n${out}")
endif()
run_class(${OUT}/stopped "GEOMECH_UNUSED=1" 1 --fresh)
if(out MATCHES "unchanged")
  message(FATAL_ERROR "control: --fresh resumed something:\n${out}")
endif()
# A --fresh run stopped after one leaves a summary and a gradebook of this run (one
# checked, three not yet), not the previous run's complete ones beside deleted results.
run_class(${OUT}/stopped "GEOMECH_TEST_STOP_AFTER=1:INT" signal --fresh)
file(READ ${OUT}/stopped/summary.md partial)
if(NOT partial MATCHES "In progress: 1 of 4 implementations checked")
  message(FATAL_ERROR "a --fresh run stopped after one does not say so in its summary:\n${partial}")
endif()
expect_no_grade_rows(${OUT}/stopped.csv 3)
if(NOT out MATCHES "resumes, checking only those:\n  [^\n]*check-class" OR out MATCHES "checking only those:\n  [^\n]*--fresh")
  message(FATAL_ERROR "the resume command of a --fresh run must not repeat --fresh:\n${out}")
endif()

# A lecturer's term: --regrade NAME checks that student again and resumes the rest, the
# summary the same; a name not in the class is refused before anything runs, with the closest one.
run_class(${OUT}/full "GEOMECH_UNUSED=1" 1)  # up to date with numpy_double_only.py changed above
file(READ ${OUT}/full/summary.md full)
run_class(${OUT}/full "GEOMECH_UNUSED=1" 1 --regrade wrong_vee)
if(NOT out MATCHES "checked again on request: 1 named \\(--regrade\\), 0 last NOT CHECKED" OR
   NOT out MATCHES "3 of 4 implementations are unchanged")
  message(FATAL_ERROR "--regrade wrong_vee should check it alone again:\n${out}")
endif()
file(READ ${OUT}/full/summary.md regraded)
if(NOT regraded STREQUAL full)
  message(FATAL_ERROR "a regrade of an unchanged student changed the summary:\n${regraded}\n---\n${full}")
endif()
run_class(${OUT}/full "GEOMECH_UNUSED=1" 2 --regrade wrong_vea)
if(NOT out MATCHES "--regrade wrong_vea: no implementation of that name[^\n]*did you mean \"wrong_vee\"")
  message(FATAL_ERROR "an unknown --regrade name should be refused with the closest name:\n${out}")
endif()
# --not-checked: a run whose every check ran out of its time leaves NOT CHECKED rows (the time is
# not part of a row's fingerprint); the next run resumes them as they are, unless --not-checked,
# which checks exactly those again, to the uninterrupted run's summary.
# (exit 2 when nothing was checked: no gradebook can be written, and the run says so; exit 1 when a
# check ended before the limit was first looked at, as the Octave one may with the cores to itself)
run_class(${OUT}/full "GEOMECH_UNUSED=1" "1|2" --fresh --timeout-per-implementation 0.05)
file(READ ${OUT}/full/summary.md starved)
string(REGEX MATCHALL "NOT CHECKED" nc "${starved}")
list(LENGTH nc n_nc)
if(n_nc LESS 1)
  message(FATAL_ERROR "control: a 0.05 s limit should leave NOT CHECKED rows:\n${starved}")
endif()
run_class(${OUT}/full "GEOMECH_UNUSED=1" "1|2")
file(READ ${OUT}/full/summary.md kept)
if(NOT kept STREQUAL starved)
  message(FATAL_ERROR "control: without --not-checked the NOT CHECKED rows are resumed as they are:\n${kept}")
endif()
run_class(${OUT}/full "GEOMECH_UNUSED=1" 1 --not-checked)
if(NOT out MATCHES "0 named \\(--regrade\\), [1-4] last NOT CHECKED \\(--not-checked\\)")
  message(FATAL_ERROR "--not-checked should check the NOT CHECKED rows again:\n${out}")
endif()
file(READ ${OUT}/full/summary.md rechecked)
if(NOT rechecked STREQUAL full)
  message(FATAL_ERROR "after --not-checked the summary should be the uninterrupted run's:\n${rechecked}\n---\n${full}")
endif()
# Two defects once seen, kept fixed: a refused rubric leaves no report folder behind; the roster's warnings reach
# the summary (a student with no roster row is graded under their implementation's name).
file(WRITE ${OUT}/bad_rubric.json "{\"slots\": {\"vei\": 1}}")
run_class(${OUT}/refused "GEOMECH_UNUSED=1" 2 --rubric ${OUT}/bad_rubric.json)
if(EXISTS ${OUT}/refused OR NOT out MATCHES "vei")
  message(FATAL_ERROR "a refused rubric should name its slot and leave no report folder:\n${out}")
endif()
file(WRITE ${OUT}/roster.csv "name,full_name,username,email,id_number\nwrong_vee,W V,wv,wv@uni.example,S1\n"
                             "numpy_double_only,N D,nd,nd@uni.example,S2\nbug_elementwise,B E,be,be@uni.example,S3\n")
run_class(${OUT}/full "GEOMECH_UNUSED=1" 1 --roster ${OUT}/roster.csv)
file(READ ${OUT}/full/summary.md rostered)
if(NOT rostered MATCHES "## Roster\n\n- \"octave_folder\" has no roster row")
  message(FATAL_ERROR "the summary should carry the roster's warning about octave_folder:\n${rostered}")
endif()
message(STATUS "private folder checked; interrupted twice and resumed to the same summary and gradebook; regraded")
