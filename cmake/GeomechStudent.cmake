# Student implementations.
#
# 1. The prebuilt main() of a student check program (tools/student_check_main.cpp), compiled once.
# 2. student/toolchain.json in the build tree: the compiler, flags and prebuilt files with which
#    `geomech check FILE.cpp` compiles only the student's file and links it (harness/program/build.cpp).
# 3. geomech_add_student(<target> <source>...): the same program as a CMake target, used for the
#    examples (examples/students) and usable by anyone building inside this tree.

add_library(geomech_student_driver OBJECT ${PROJECT_SOURCE_DIR}/tools/student_check_main.cpp)
target_link_libraries(geomech_student_driver PRIVATE geomech_harness)
# 1b. The main() of the C++ protocol server of untrusted mode (tools/student_server_main.cpp).
add_library(geomech_server_driver OBJECT ${PROJECT_SOURCE_DIR}/tools/student_server_main.cpp)
target_link_libraries(geomech_server_driver PRIVATE geomech_harness)
# Both read the suite's precompiled headers (the same flags as the suite's libraries).
target_precompile_headers(geomech_student_driver REUSE_FROM ${GM_PCH_OWNER})
target_precompile_headers(geomech_server_driver REUSE_FROM ${GM_PCH_OWNER})

# Optimisation of student code: -O1 for every scalar. Measured on examples/students/correct.cpp
# (CPU seconds to compile double / mp50 / exact): -O0 4.9 / 6.7 / 5.6, -O1 4.7 / 7.4 / 6.2,
# -O2 6.0 / 9.4 / 9.0. -O1 is within a second of -O0 in total and keeps the 50-digit and rational
# arithmetic (all of it Boost templates instantiated in the student's file) optimised.
set(GM_STUDENT_OPT_DOUBLE -O1)
set(GM_STUDENT_OPT_MP50 -O1)
set(GM_STUDENT_OPT_EXACT -O1)

# A sanitized suite (the preset "sanitize") is linked with the sanitizer runtimes, so student code
# is compiled and linked with the same instrumentation flags as the suite, and with -gz: the
# libraries' debug sections are compressed, and a link without -gz would write them out
# uncompressed (about 4x larger per student program).
string(TOUPPER "${CMAKE_BUILD_TYPE}" _gm_build_type)
separate_arguments(_gm_build_flags UNIX_COMMAND "${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${_gm_build_type}}")
set(_gm_instrumentation "")
foreach(_f IN LISTS _gm_build_flags)
  if(_f MATCHES "^-f(no-)?sanitize" OR _f STREQUAL "-fno-omit-frame-pointer" OR _f STREQUAL "-gz")
    list(APPEND _gm_instrumentation ${_f})
  endif()
endforeach()

# The elements of a CMake list as JSON strings: a;b -> "a", "b" (the paths and flags here hold no
# quotes or backslashes).
function(_gm_json_strings out)
  list(TRANSFORM ARGN PREPEND "\"")
  list(TRANSFORM ARGN APPEND "\"")
  list(JOIN ARGN ", " _joined)
  set(${out} "${_joined}" PARENT_SCOPE)
endfunction()

get_target_property(_gm_eigen_inc Eigen3::Eigen INTERFACE_INCLUDE_DIRECTORIES)
set(_gm_student_includes ${PROJECT_SOURCE_DIR} ${PROJECT_SOURCE_DIR}/student ${_gm_eigen_inc} ${Boost_INCLUDE_DIRS})
list(REMOVE_DUPLICATES _gm_student_includes)
list(REMOVE_ITEM _gm_student_includes /usr/include)
_gm_json_strings(_gm_inc_json ${_gm_student_includes})
# -Wno-ignored-attributes: Eigen silences this warning about its SIMD packet types with pragmas
# inside its headers, and GCC does not keep those pragmas' scope in a precompiled header, so a
# student would see about 150 lines of it from Eigen's internals.
# In the sanitized build, Eigen's choice of allocator as in the library (CMakeLists.txt,
# GM_EIGEN_MALLOC_DEFINITION).
set(_gm_eigen_malloc "")
if(GM_EIGEN_MALLOC_DEFINITION)
  set(_gm_eigen_malloc -D${GM_EIGEN_MALLOC_DEFINITION})
endif()
set(_gm_student_flags -std=c++20 -DBOOST_ALL_NO_LIB -DGEOMECH_EIGEN_KERNELS_PREBUILT ${_gm_eigen_malloc} -Wall -Wextra
    -Wno-deprecated-copy -Wno-maybe-uninitialized -Wno-ignored-attributes ${GM_GCC_MEMORY_FLAGS}
    ${_gm_instrumentation})
_gm_json_strings(_gm_flags_json ${_gm_student_flags})

# 2b. geomech/student.hpp precompiled with exactly the flags of a student compile (GCC uses a
#     precompiled header only then): `geomech check` includes student/pch/geomech_student_pch.hpp
#     first, and the compiler reads the .gch beside it instead of parsing Eigen, Boost and the
#     suite's headers again (about 3.5 s of each of the three compiles). One copy serves all three
#     scalars (see register_all in student.hpp). If the .gch is missing or does not match, the
#     compiler silently parses the header instead: slower, same result.
if(NOT GM_STUDENT_OPT_DOUBLE STREQUAL GM_STUDENT_OPT_MP50 OR NOT GM_STUDENT_OPT_EXACT STREQUAL GM_STUDENT_OPT_MP50)
  message(FATAL_ERROR "the student precompiled header assumes one optimisation flag for all scalars")
endif()
set(GM_STUDENT_PCH ${CMAKE_BINARY_DIR}/student/pch/geomech_student_pch.hpp)
file(GENERATE OUTPUT ${GM_STUDENT_PCH} CONTENT "// Generated: what `geomech check` precompiles for a student's file.\n#include <geomech/student.hpp>\n")
list(TRANSFORM _gm_student_includes PREPEND "-I" OUTPUT_VARIABLE _gm_student_include_flags)
add_custom_command(
  OUTPUT ${GM_STUDENT_PCH}.gch
  COMMAND ${CMAKE_CXX_COMPILER} ${_gm_student_flags} ${GM_STUDENT_OPT_MP50} -fdiagnostics-color=never
          -DGEOMECH_STUDENT_CHECK=1 ${_gm_student_include_flags} -MD -MF ${GM_STUDENT_PCH}.d
          -x c++-header ${GM_STUDENT_PCH} -o ${GM_STUDENT_PCH}.gch
  DEPENDS ${GM_STUDENT_PCH} ${PROJECT_SOURCE_DIR}/student/geomech/student.hpp
  DEPFILE ${GM_STUDENT_PCH}.d
  COMMENT "Precompiling geomech/student.hpp for student checks"
  VERBATIM)
add_custom_target(geomech_student_pch ALL DEPENDS ${GM_STUDENT_PCH}.gch)
_gm_json_strings(_gm_link_json ${_gm_instrumentation})
# What the harness links besides the suite's archives: RapidCheck, and libcmark-gfm (report.html).
_gm_json_strings(_gm_other_libraries_json $<TARGET_LINKER_FILE:rapidcheck> ${GM_CMARK_LIBRARIES})

file(GENERATE OUTPUT ${CMAKE_BINARY_DIR}/student/toolchain.json CONTENT "{
  \"format\": \"geomech-student-toolchain 1\",
  \"cxx\": \"${CMAKE_CXX_COMPILER}\",
  \"flags\": [${_gm_flags_json}],
  \"link_flags\": [${_gm_link_json}],
  \"includes\": [${_gm_inc_json}],
  \"opt\": {\"double\": \"${GM_STUDENT_OPT_DOUBLE}\", \"mp50\": \"${GM_STUDENT_OPT_MP50}\", \"exact\": \"${GM_STUDENT_OPT_EXACT}\"},
  \"driver_object\": \"$<TARGET_OBJECTS:geomech_student_driver>\",
  \"server_object\": \"$<TARGET_OBJECTS:geomech_server_driver>\",
  \"harness_library\": \"$<TARGET_FILE:geomech_harness>\",
  \"property_library\": \"$<TARGET_FILE:geomech>\",
  \"other_libraries\": [${_gm_other_libraries_json}],
  \"precompiled_header\": \"${GM_STUDENT_PCH}\",
  \"cache_dir\": \"${CMAKE_BINARY_DIR}/student-cache\"
}
")

# geomech_add_student(<target> <source>...): a check program for the student sources. Each source
# is compiled once, for all three scalars (the `geomech check` tool instead compiles one copy per
# scalar in parallel, and leaves out what does not compile in a scalar; here a slot that does not
# compile for a scalar is a build error: declare skip_exact / skip_mp50, see student.hpp).
# All such targets read the precompiled geomech/student.hpp that `geomech check` reads (2b above), so
# that the examples compile exactly as a student's file does and no second copy of that header is
# precompiled (17 CPU-s); OBJECT_DEPENDS rebuilds them when it changes. -Wno-ignored-attributes as
# for a student (see above).
function(geomech_add_student target)
  add_executable(${target} ${ARGN} $<TARGET_OBJECTS:geomech_student_driver>)
  target_compile_definitions(${target} PRIVATE GEOMECH_STUDENT_CHECK=1)
  target_compile_options(${target} PRIVATE ${GM_STUDENT_OPT_MP50} -Wno-ignored-attributes -Winvalid-pch
                                           -include ${GM_STUDENT_PCH})
  target_link_libraries(${target} PRIVATE geomech_harness)
  add_dependencies(${target} geomech_student_pch)
  set_property(SOURCE ${ARGN} TARGET_DIRECTORY ${target} APPEND PROPERTY OBJECT_DEPENDS ${GM_STUDENT_PCH}.gch)
endfunction()

# 4. For a project outside this tree: build/student/GeomechStudentConfig.cmake, so that
#      find_package(GeomechStudent REQUIRED PATHS <this build>/student)
#      geomech_add_student(check my_rigid_body.cpp)
#    builds the same check program against the prebuilt files of this build.
set(_gm_inc_cmake "")
set(_gm_eigen_malloc_list "")
if(GM_EIGEN_MALLOC_DEFINITION)
  set(_gm_eigen_malloc_list ";${GM_EIGEN_MALLOC_DEFINITION}")
endif()
string(JOIN ";" _gm_inc_cmake ${_gm_student_includes})
string(JOIN ";" _gm_cmark_cmake ${GM_CMARK_LIBRARIES})
file(GENERATE OUTPUT ${CMAKE_BINARY_DIR}/student/GeomechStudentConfig.cmake CONTENT "# Generated by the geomech-spec build in ${CMAKE_BINARY_DIR}; do not edit.
# A student's own CMake project: find_package(GeomechStudent REQUIRED PATHS ${CMAKE_BINARY_DIR}/student)
# then geomech_add_student(<target> <source>...). The sources are compiled once for double, 50 digits
# and exact rationals (declare skip_exact / skip_mp50 for slots that cannot compile in a scalar).
if(NOT TARGET geomech_student_prebuilt)
  add_library(geomech_student_prebuilt INTERFACE IMPORTED)
  set_target_properties(geomech_student_prebuilt PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES \"${_gm_inc_cmake}\"
    INTERFACE_COMPILE_DEFINITIONS \"BOOST_ALL_NO_LIB;GEOMECH_EIGEN_KERNELS_PREBUILT;GEOMECH_STUDENT_CHECK=1${_gm_eigen_malloc_list}\"
    INTERFACE_COMPILE_FEATURES \"cxx_std_20\"
    INTERFACE_COMPILE_OPTIONS \"${_gm_instrumentation}\"
    INTERFACE_LINK_OPTIONS \"${_gm_instrumentation}\"
    INTERFACE_LINK_LIBRARIES \"$<TARGET_OBJECTS:geomech_student_driver>;$<TARGET_FILE:geomech_harness>;-Wl,--whole-archive;$<TARGET_FILE:geomech>;-Wl,--no-whole-archive;$<TARGET_LINKER_FILE:rapidcheck>;${_gm_cmark_cmake}\")
endif()
function(geomech_add_student target)
  add_executable(\${target} \${ARGN})
  target_link_libraries(\${target} PRIVATE geomech_student_prebuilt)
  target_compile_options(\${target} PRIVATE ${GM_STUDENT_OPT_MP50})
endfunction()
")
