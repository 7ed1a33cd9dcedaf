# The class report as a page, opened in a real browser: Debian's chromium, headless, as a
# lecturer opens summary.html from the report folder (file://, no server, no network).
#   cmake -DGEOMECH=... -DSOURCE=<repo> -DOUT=dir [-DCONTROL=ON] -P run_class_html.cmake
# A small class from examples/class (narrowed checks) is checked; then summary.html, opened as
# summary.html#sort=-grade, must render with no console message at all (no script error, no
# blocked load), hold the class table sorted by the grade (the page's script ran), a row per student
# (the roster's student without a submission too), and link each student's report.html, which must
# render with its figure inline; the class section's numbers, read back from the rendered page, must
# be summary.md's. CONTROL=ON opens a page with a script error and a load from the
# network instead, and asserts that both are seen: the console check can fail.
find_program(CHROMIUM NAMES chromium chromium-browser)
if(NOT CHROMIUM)
  message(FATAL_ERROR "chromium is not installed: apt-get install -y chromium (./geomech test installs it)")
endif()
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

# The page at URL, as chromium renders it: its DOM after scripts ran, and every console line.
function(open_page url dom_var console_var)
  execute_process(COMMAND ${CHROMIUM} --headless --no-sandbox --disable-gpu --disable-quic --no-first-run
                          --disable-background-networking --disable-component-update --disable-sync
                          --user-data-dir=${OUT}/browser-profile --enable-logging=stderr --v=0 --dump-dom ${url}
                  RESULT_VARIABLE status OUTPUT_VARIABLE dom ERROR_VARIABLE log TIMEOUT 120)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "chromium could not open ${url} (${status}):\n${log}")
  endif()
  string(REGEX MATCHALL "[^\n]*:CONSOLE[^\n]*" console "${log}")
  set(${dom_var} "${dom}" PARENT_SCOPE)
  set(${console_var} "${console}" PARENT_SCOPE)
endfunction()

if(CONTROL)
  file(WRITE ${OUT}/broken.html "<!DOCTYPE html><html><head><meta http-equiv=\"Content-Security-Policy\" "
       "content=\"default-src 'none'; img-src data:; script-src 'unsafe-inline'\"></head><body>"
       "<img src=\"http://example.org/x.png\"><script>notDefined();</script></body></html>\n")
  open_page(file://${OUT}/broken.html dom console)
  if(NOT console MATCHES "Uncaught ReferenceError" OR NOT console MATCHES "Content Security Policy")
    message(FATAL_ERROR "control: chromium's console did not show the script error and the blocked load:\n${console}")
  endif()
  message(STATUS "control: the console check sees a script error and a blocked network load")
  return()
endif()

set(class ${OUT}/class)
file(MAKE_DIRECTORY ${class})
foreach(f alice.py frank.py dave)
  file(COPY ${SOURCE}/examples/class/submissions/${f} DESTINATION ${class})
endforeach()
execute_process(COMMAND ${GEOMECH} check-class ${class} --report ${OUT}/reports --parallel 2
                        --rubric ${SOURCE}/examples/class/rubric.json --roster ${SOURCE}/examples/class/roster.csv
                        --grades ${OUT}/grades.csv --scalar double -p definition_hat -p definition_vee -p definition_casimir
                        -p definition_manakov_Omega -p definition_manakov_2_34 -p integrator_order
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT EXISTS ${OUT}/reports/summary.html)
  message(FATAL_ERROR "check-class wrote no summary.html (status ${status}):\n${out}${err}")
endif()

open_page("file://${OUT}/reports/summary.html#sort=-grade" dom console)
if(console)
  message(FATAL_ERROR "summary.html logged to the console:\n${console}")
endif()
foreach(text "<table id=\"class-table\">" "aria-sort=\"descending\"" "id=\"row-alice\"" "id=\"row-frank\""
             "id=\"row-dave\"" "id=\"row-henry\"" "NO SUBMISSION" "INCOMPLETE" "<a href=\"alice/report.html\">alice</a>")
  string(FIND "${dom}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "summary.html as rendered lacks: ${text}\n${dom}")
  endif()
endforeach()
# Sorted by the grade, highest first: alice's row before dave's, dave's before henry's.
string(FIND "${dom}" "id=\"row-alice\"" a)
string(FIND "${dom}" "id=\"row-dave\"" d)
string(FIND "${dom}" "id=\"row-henry\"" h)
if(NOT (a LESS d AND d LESS h))
  message(FATAL_ERROR "summary.html#sort=-grade did not sort by the grade (alice ${a}, dave ${d}, henry ${h})")
endif()

# What the class got wrong, rendered: each row of summary.md's table is read back from the page, its
# count in the table and beside its bar in the chart (dave's manakov_Omega, and manakov_2_34 through it).
file(READ ${OUT}/reports/summary.md md)
string(REGEX MATCHALL "\\| slot `[A-Za-z_0-9]+` \\| [0-9]+ of [0-9]+ \\|" rows "${md}")
list(LENGTH rows n_rows)
if(n_rows LESS 2)
  message(FATAL_ERROR "summary.md's class section lists ${n_rows} wrong slots, expected manakov_Omega and manakov_2_34:\n${md}")
endif()
foreach(row IN LISTS rows)
  string(REGEX MATCH "`([A-Za-z_0-9]+)` \\| ([0-9]+ of [0-9]+)" _ "${row}")
  set(slot ${CMAKE_MATCH_1})
  set(count ${CMAKE_MATCH_2})
  foreach(text "<code>${slot}</code></td><td>${count}</td>" ">slot ${slot}</text>" "id=\"wrong-table\"")
    string(FIND "${dom}" "${text}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "summary.html as rendered lacks what summary.md says of ${slot} (${count}): ${text}")
    endif()
  endforeach()
  string(FIND "${dom}" ">slot ${slot}</text>" bar)
  string(SUBSTRING "${dom}" ${bar} 400 bar_text)
  if(NOT bar_text MATCHES "^[^\n]*>${count}</text>")
    message(FATAL_ERROR "the bar of ${slot} does not say ${count}: ${bar_text}")
  endif()
endforeach()
if(NOT md MATCHES "slot `manakov_Omega` \\| 1 of 3 \\| dave")
  message(FATAL_ERROR "summary.md does not say that dave, 1 of the 3 checked, got manakov_Omega wrong:\n${md}")
endif()

open_page("file://${OUT}/reports/alice/report.html" dom console)
if(console)
  message(FATAL_ERROR "alice/report.html logged to the console:\n${console}")
endif()
foreach(text "<h1 id=\"geomech-report-alice\">" "<img src=\"data:image/svg+xml;base64," "<table>")
  string(FIND "${dom}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "alice/report.html as rendered lacks: ${text}\n${dom}")
  endif()
endforeach()
message(STATUS "summary.html and alice/report.html render in chromium, sorted, with no console message")
