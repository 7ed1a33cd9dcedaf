# Student implementations.
#
# 1. The prebuilt main() of a student check program (student/driver.cpp), compiled once.
# 2. student/toolchain.json in the build tree: the compiler, flags and prebuilt files with which
#    `geomech check FILE.cpp` compiles only the student's file and links it (harness/build.cpp).
# 3. geomech_add_student(<target> <source>...): the same program as a CMake target, used for the
#    examples (examples/students) and usable by anyone building inside this tree.

add_library(geomech_student_driver OBJECT ${PROJECT_SOURCE_DIR}/student/driver.cpp)
target_link_libraries(geomech_student_driver PRIVATE geomech_harness)

# Optimisation of student code: -O1 for every scalar. Measured on examples/students/correct.cpp
# (CPU seconds to compile double / mp50 / exact): -O0 4.9 / 6.7 / 5.6, -O1 4.7 / 7.4 / 6.2,
# -O2 6.0 / 9.4 / 9.0. -O1 is within a second of -O0 in total and keeps the 50-digit and rational
# arithmetic (all of it Boost templates instantiated in the student's file) optimised.
set(GM_STUDENT_OPT_DOUBLE -O1)
set(GM_STUDENT_OPT_MP50 -O1)
set(GM_STUDENT_OPT_EXACT -O1)

get_target_property(_gm_eigen_inc Eigen3::Eigen INTERFACE_INCLUDE_DIRECTORIES)
set(_gm_student_includes ${PROJECT_SOURCE_DIR} ${PROJECT_SOURCE_DIR}/student ${_gm_eigen_inc} ${Boost_INCLUDE_DIRS})
list(REMOVE_DUPLICATES _gm_student_includes)
list(REMOVE_ITEM _gm_student_includes /usr/include)
set(_gm_inc_json "")
foreach(_d IN LISTS _gm_student_includes)
  if(_gm_inc_json)
    string(APPEND _gm_inc_json ", ")
  endif()
  string(APPEND _gm_inc_json "\"${_d}\"")
endforeach()

file(GENERATE OUTPUT ${CMAKE_BINARY_DIR}/student/toolchain.json CONTENT "{
  \"format\": \"geomech-student-toolchain 1\",
  \"cxx\": \"${CMAKE_CXX_COMPILER}\",
  \"flags\": [\"-std=c++20\", \"-DBOOST_ALL_NO_LIB\", \"-Wall\", \"-Wextra\", \"-Wno-deprecated-copy\", \"-Wno-maybe-uninitialized\"],
  \"includes\": [${_gm_inc_json}],
  \"opt\": {\"double\": \"${GM_STUDENT_OPT_DOUBLE}\", \"mp50\": \"${GM_STUDENT_OPT_MP50}\", \"exact\": \"${GM_STUDENT_OPT_EXACT}\"},
  \"driver_object\": \"$<TARGET_OBJECTS:geomech_student_driver>\",
  \"harness_library\": \"$<TARGET_FILE:geomech_harness>\",
  \"property_library\": \"$<TARGET_FILE:geomech>\",
  \"other_libraries\": [\"$<TARGET_LINKER_FILE:rapidcheck>\"],
  \"cache_dir\": \"${CMAKE_BINARY_DIR}/student-cache\"
}
")

# geomech_add_student(<target> <source>...): a check program for the student sources. Each source
# is compiled once, for all three scalars (the `geomech check` tool instead compiles one copy per
# scalar in parallel, and leaves out what does not compile in a scalar; here a slot that does not
# compile for a scalar is a build error: declare skip_exact / skip_mp50, see student.hpp).
function(geomech_add_student target)
  add_executable(${target} ${ARGN} $<TARGET_OBJECTS:geomech_student_driver>)
  target_compile_definitions(${target} PRIVATE GEOMECH_STUDENT_CHECK=1)
  target_compile_options(${target} PRIVATE ${GM_STUDENT_OPT_MP50})
  target_link_libraries(${target} PRIVATE geomech_harness)
endfunction()
