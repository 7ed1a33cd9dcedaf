# ctest: the installed suite used from outside its source tree.
#   cmake -DBUILD=<suite build dir> -DSOURCE=<suite source dir> -DWORK=<scratch dir> -DMODE=install|deb -P install_test.cmake
# install: cmake --install to a temporary prefix, configure tests/install/consumer against it with
#          find_package(GeomechSpec), build it, run its ctest (JUnit written), and run the installed
#          tool on the consumer's file.
# deb:     cpack -G DEB, then the package's contents, extracted, run.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(last_output "${out}${err}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
if(MODE STREQUAL "install")
  run(${CMAKE_COMMAND} --install ${BUILD} --prefix ${WORK}/prefix)
  foreach(f bin/geomech share/geomech-spec/toolchain.json lib/cmake/GeomechSpec/GeomechSpecConfig.cmake
            include/geomech-spec/geomech/student.hpp share/geomech-spec/student/python/geomech_server.py
            share/geomech-spec/student/octave/geomech_server.m)
    if(NOT EXISTS ${WORK}/prefix/${f})
      message(FATAL_ERROR "the install has no ${f}")
    endif()
  endforeach()
  file(COPY ${SOURCE}/tests/install/consumer/ DESTINATION ${WORK}/consumer)
  run(${CMAKE_COMMAND} -S ${WORK}/consumer -B ${WORK}/consumer/build -DCMAKE_PREFIX_PATH=${WORK}/prefix
      -DCMAKE_BUILD_TYPE=Release)
  run(${CMAKE_COMMAND} --build ${WORK}/consumer/build)
  run(${CMAKE_CTEST_COMMAND} --test-dir ${WORK}/consumer/build --output-on-failure)
  if(NOT EXISTS ${WORK}/consumer/build/geomech-my_rigid_body.junit.xml)
    message(FATAL_ERROR "the consumer's check wrote no JUnit XML")
  endif()
  # geomech_add_check(... PKG ode LIBRARIES m): both on the check program's link line.
  file(GLOB_RECURSE link_files ${WORK}/consumer/build/CMakeFiles/geomech_check_my_rigid_body.dir/link.txt)
  file(READ ${link_files} link_line)
  if(NOT link_line MATCHES "(-lode|libode[.]so)" OR NOT link_line MATCHES "-lm( |$)")
    message(FATAL_ERROR "geomech_add_check did not link its PKG ode and LIBRARIES m:\n${link_line}")
  endif()
  file(READ ${WORK}/consumer/build/geomech-my_rigid_body.junit.xml junit)
  if(NOT junit MATCHES "definition_euler_3_8")
    message(FATAL_ERROR "the JUnit XML does not list definition_euler_3_8")
  endif()
  # The installed tool compiles a file by itself, with the installed toolchain (paths relative to it).
  run(${WORK}/prefix/bin/geomech check ${WORK}/consumer/my_rigid_body.cpp --quiet --scalar double
      --cache-dir ${WORK}/cache --report ${WORK}/report)
  if(NOT last_output MATCHES "PASS")
    message(FATAL_ERROR "the installed tool did not pass the consumer's file:\n${last_output}")
  endif()
  # A Python implementation, through the protocol server installed beside the tool.
  file(COPY ${SOURCE}/examples/students/correct.py DESTINATION ${WORK}/python)
  run(${WORK}/prefix/bin/geomech check ${WORK}/python/correct.py --quiet --scalar double -p definition_hat
      -p definition_casimir --report ${WORK}/python-report)
  if(NOT last_output MATCHES "PASS")
    message(FATAL_ERROR "the installed tool did not pass correct.py:\n${last_output}")
  endif()
  message(STATUS "installed, found with find_package, checked from outside the source tree: ${last_output}")
elseif(MODE STREQUAL "deb")
  run(cpack -G DEB -B ${WORK}/package --config ${BUILD}/CPackConfig.cmake)
  file(GLOB debs ${WORK}/package/*.deb)
  list(LENGTH debs n)
  if(NOT n EQUAL 1)
    message(FATAL_ERROR "expected one .deb in ${WORK}/package, found ${n}")
  endif()
  run(dpkg-deb --info ${debs})
  if(NOT last_output MATCHES "Depends: .*librapidcheck-dev")
    message(FATAL_ERROR "the package does not depend on librapidcheck-dev:\n${last_output}")
  endif()
  run(dpkg-deb -x ${debs} ${WORK}/root)
  run(${WORK}/root/usr/bin/geomech slots)
  if(NOT last_output MATCHES "euler_3_8")
    message(FATAL_ERROR "the packaged tool does not list the slots")
  endif()
  file(SIZE ${debs} size)
  message(STATUS "Debian package ${debs}: ${size} bytes; its geomech runs")
else()
  message(FATAL_ERROR "MODE must be install or deb")
endif()
