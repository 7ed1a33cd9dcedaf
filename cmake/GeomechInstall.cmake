# Installing the suite: `cmake --install build --prefix P` puts in place
#   P/bin/geomech                              the tool (geomech check FILE.cpp works from there)
#   P/bin/geomech-octave-server                Octave's protocol server, where liboctave-dev was installed
#   P/lib/geomech-spec/                        the prebuilt property and harness libraries, the check program's main
#   P/include/geomech-spec/                    geomech/student.hpp and the core headers it includes
#   P/share/geomech-spec/                      toolchain.json (paths relative to itself), spec/catalogue.json, quick_profile.json and thorough_only.json,
#                                              the Python and Octave protocol servers
#   P/lib/cmake/GeomechSpec/                   find_package(GeomechSpec): GeomechSpec::student, geomech_add_check()
# and `cpack -G DEB` (in the build tree) packs the same tree as a Debian package.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(GM_INSTALL_LIBDIR ${CMAKE_INSTALL_LIBDIR}/geomech-spec)
set(GM_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/geomech-spec)
set(GM_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/geomech-spec)
set(GM_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/GeomechSpec)

install(TARGETS geomech_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET geomech_octave_server)  # beside the tool, where it looks for it (harness/remote/remote_subject.cpp)
  install(TARGETS geomech_octave_server RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(FILES $<TARGET_FILE:geomech> $<TARGET_FILE:geomech_harness> DESTINATION ${GM_INSTALL_LIBDIR})
install(FILES $<TARGET_OBJECTS:geomech_student_driver> DESTINATION ${GM_INSTALL_LIBDIR} RENAME geomech_student_driver.o)
install(FILES $<TARGET_OBJECTS:geomech_server_driver> DESTINATION ${GM_INSTALL_LIBDIR} RENAME geomech_server_driver.o)
install(DIRECTORY core/ DESTINATION ${GM_INSTALL_INCLUDEDIR}/core FILES_MATCHING PATTERN "*.hpp")
install(FILES student/geomech/student.hpp DESTINATION ${GM_INSTALL_INCLUDEDIR}/geomech)
install(FILES student/geomech/detail/scalar_selection.hpp DESTINATION ${GM_INSTALL_INCLUDEDIR}/geomech/detail)
install(FILES spec/catalogue.json spec/quick_profile.json spec/thorough_only.json DESTINATION ${GM_INSTALL_DATADIR}/spec)
# The protocol servers that run Python, Octave and JavaScript implementations (core/data_path.hpp finds them).
install(FILES student/python/geomech_server.py DESTINATION ${GM_INSTALL_DATADIR}/student/python)
install(FILES student/octave/geomech_server.m DESTINATION ${GM_INSTALL_DATADIR}/student/octave)
install(FILES student/javascript/geomech_server.mjs DESTINATION ${GM_INSTALL_DATADIR}/student/javascript)

# The installed toolchain of `geomech check FILE.cpp`, with the prebuilt files named relative to
# share/geomech-spec/, so that the tree still works after it is moved.
file(RELATIVE_PATH _gm_rel_lib ${CMAKE_INSTALL_FULL_DATADIR}/geomech-spec ${CMAKE_INSTALL_FULL_LIBDIR}/geomech-spec)
file(RELATIVE_PATH _gm_rel_inc ${CMAKE_INSTALL_FULL_DATADIR}/geomech-spec ${CMAKE_INSTALL_FULL_INCLUDEDIR}/geomech-spec)
set(_gm_installed_includes ${_gm_rel_inc} ${_gm_eigen_inc} ${Boost_INCLUDE_DIRS})
list(REMOVE_DUPLICATES _gm_installed_includes)
list(REMOVE_ITEM _gm_installed_includes /usr/include)
_gm_json_strings(_gm_installed_inc_json ${_gm_installed_includes})
file(GENERATE OUTPUT ${CMAKE_BINARY_DIR}/student/installed-toolchain.json CONTENT "{
  \"format\": \"geomech-student-toolchain 1\",
  \"cxx\": \"${CMAKE_CXX_COMPILER}\",
  \"flags\": [${_gm_flags_json}],
  \"link_flags\": [${_gm_link_json}],
  \"includes\": [${_gm_installed_inc_json}],
  \"opt\": {\"double\": \"${GM_STUDENT_OPT_DOUBLE}\", \"mp50\": \"${GM_STUDENT_OPT_MP50}\", \"exact\": \"${GM_STUDENT_OPT_EXACT}\"},
  \"driver_object\": \"${_gm_rel_lib}/geomech_student_driver.o\",
  \"server_object\": \"${_gm_rel_lib}/geomech_server_driver.o\",
  \"harness_library\": \"${_gm_rel_lib}/$<TARGET_FILE_NAME:geomech_harness>\",
  \"property_library\": \"${_gm_rel_lib}/$<TARGET_FILE_NAME:geomech>\",
  \"other_libraries\": [${_gm_other_libraries_json}],
  \"cache_dir\": \"\"
}
")
install(FILES ${CMAKE_BINARY_DIR}/student/installed-toolchain.json DESTINATION ${GM_INSTALL_DATADIR} RENAME toolchain.json)

# A sanitized build's libraries link only into programs built with the same instrumentation
# (cmake/GeomechStudent.cmake), so its package config carries those flags (empty in Release).
string(JOIN ";" GM_INSTALLED_INSTRUMENTATION ${_gm_instrumentation})
configure_package_config_file(cmake/GeomechSpecConfig.cmake.in ${CMAKE_BINARY_DIR}/GeomechSpecConfig.cmake
  INSTALL_DESTINATION ${GM_INSTALL_CMAKEDIR}
  PATH_VARS GM_INSTALL_LIBDIR GM_INSTALL_INCLUDEDIR CMAKE_INSTALL_BINDIR)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/GeomechSpecConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_BINARY_DIR}/GeomechSpecConfig.cmake ${CMAKE_BINARY_DIR}/GeomechSpecConfigVersion.cmake
  DESTINATION ${GM_INSTALL_CMAKEDIR})

# A Debian package of the installed tree: `cpack -G DEB --config build/CPackConfig.cmake`.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME geomech-spec)
set(CPACK_PACKAGE_VENDOR "geomech-spec")
set(CPACK_PACKAGE_CONTACT "geomech-spec developers <geomech-spec@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Rigid-body lecture notes as an executable specification: check your implementation")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# What a student's own file needs to compile and link against the installed libraries.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "g++ (>= 12), cmake (>= 3.25), libeigen3-dev (>= 3.4), librapidcheck-dev, libboost-dev (>= 1.74), libflint-arb2, libcmark-gfm-dev, libcmark-gfm-extensions-dev")
include(CPack)
