# The sanitized build's arithmetic, taken from a release build (docs/DEVELOPING.md, "The sanitized
# build"). GEOMECH_ARITHMETIC_FROM=<a release build tree of the same sources> (`./geomech sanitize`
# passes ./build, which it brings up to date first): the files the sanitized build compiles
# uninstrumented anyway (GEOMECH_ARITHMETIC_FLAGS: the property files in their unity batches, the
# numeric helpers, the Eigen kernels, the reference, the mutants and the golden generator) are not
# compiled a second time. Their archives are made from the release tree's objects, which were
# compiled from the same sources with the same optimisation (-O1) and, like them, without the
# sanitizers. What this build still compiles, instrumented, is everything else: the runner, the
# registry, the subject interface, the readers, the harness, the tool and the tests.
#
# What the release objects lack against an uninstrumented compile here: debug information (-g1) and
# frame pointers, so a sanitizer's stack trace that passes through the arithmetic names fewer frames
# there. Eigen takes the system's malloc in both trees (EIGEN_MALLOC_ALREADY_ALIGNED=1, set in
# CMakeLists.txt for every sanitized build), so a matrix allocated in one tree's code and freed in
# the other's goes back to the allocator it came from.
#
# Expects, from CMakeLists.txt: the targets geomech, geomech_reference, geomech_mutants,
# geomech_golden and geomech_mutation; GM_INSTRUMENTED_SOURCES, GM_ARITHMETIC_SOURCES, GM_UNITY_SOURCES,
# GM_REFERENCE_SOURCES, GM_MUTANT_SOURCES, GM_GOLDEN_SOURCES, GM_MUTATION_ARITHMETIC_SOURCES.

if(NOT GEOMECH_ARITHMETIC_FLAGS)
  message(FATAL_ERROR "GEOMECH_ARITHMETIC_FROM is for the sanitized build (cmake --preset sanitize), which "
                      "compiles the arithmetic uninstrumented (GEOMECH_ARITHMETIC_FLAGS)")
endif()
if(NOT GEOMECH_UNITY_BUILD)
  message(FATAL_ERROR "GEOMECH_ARITHMETIC_FROM takes the release tree's unity batches: GEOMECH_UNITY_BUILD must be ON")
endif()
get_filename_component(GM_FROM "${GEOMECH_ARITHMETIC_FROM}" ABSOLUTE)
if(NOT EXISTS "${GM_FROM}/CMakeCache.txt")
  message(FATAL_ERROR "GEOMECH_ARITHMETIC_FROM=${GEOMECH_ARITHMETIC_FROM}: not a configured build tree (no CMakeCache.txt)")
endif()
file(STRINGS "${GM_FROM}/CMakeCache.txt" gm_from_type REGEX "^CMAKE_BUILD_TYPE:")
file(STRINGS "${GM_FROM}/CMakeCache.txt" gm_from_unity REGEX "^GEOMECH_UNITY_BUILD:")
if(NOT gm_from_type MATCHES "=Release$" OR gm_from_unity MATCHES "=(OFF|0|FALSE)$")
  message(FATAL_ERROR "GEOMECH_ARITHMETIC_FROM=${GM_FROM}: the arithmetic is taken from a Release build with unity "
                      "batches (found ${gm_from_type}, ${gm_from_unity})")
endif()

# The object of SOURCE in TARGET of the release tree, as CMake's Makefile generator names it.
function(gm_release_objects out target)
  set(objects "")
  foreach(source IN LISTS ARGN)
    file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${source})
    list(APPEND objects ${GM_FROM}/CMakeFiles/${target}.dir/${rel}.o)
  endforeach()
  set(${out} ${objects} PARENT_SCOPE)
endfunction()

# The unity batches of TARGET (CMake numbers them from 0, 8 sources each, in source order).
function(gm_release_batches out target)
  list(LENGTH ARGN n)
  math(EXPR last "(${n} + 7) / 8 - 1")
  set(objects "")
  foreach(i RANGE ${last})
    list(APPEND objects ${GM_FROM}/CMakeFiles/${target}.dir/Unity/unity_${i}_cxx.cxx.o)
  endforeach()
  set(${out} ${objects} PARENT_SCOPE)
endfunction()

set(gm_property_batch_sources ${GM_UNITY_SOURCES})
list(FILTER gm_property_batch_sources INCLUDE REGEX "/properties/")
set(gm_mutant_batch_sources ${GM_UNITY_SOURCES})
list(FILTER gm_mutant_batch_sources INCLUDE REGEX "/tests/mutants/")
set(gm_mutant_alone_sources ${GM_MUTANT_SOURCES})
list(REMOVE_ITEM gm_mutant_alone_sources ${gm_mutant_batch_sources})

gm_release_batches(gm_geomech_batches geomech ${gm_property_batch_sources})
gm_release_objects(gm_geomech_arithmetic geomech ${GM_ARITHMETIC_SOURCES})
gm_release_objects(gm_reference_objects geomech_reference ${GM_REFERENCE_SOURCES})
gm_release_batches(gm_mutant_batches geomech_mutants ${gm_mutant_batch_sources})
gm_release_objects(gm_mutant_alone geomech_mutants ${gm_mutant_alone_sources})
gm_release_objects(gm_golden_objects geomech_golden ${GM_GOLDEN_SOURCES})
gm_release_objects(gm_mutation_arithmetic geomech_mutation ${GM_MUTATION_ARITHMETIC_SOURCES})

set(gm_all_release_objects ${gm_geomech_batches} ${gm_geomech_arithmetic} ${gm_reference_objects} ${gm_mutant_batches}
    ${gm_mutant_alone} ${gm_golden_objects} ${gm_mutation_arithmetic})
foreach(object IN LISTS gm_all_release_objects)
  if(NOT EXISTS ${object})
    message(FATAL_ERROR "GEOMECH_ARITHMETIC_FROM=${GM_FROM}: ${object} is missing; build that tree first "
                        "(./geomech build), or configure without GEOMECH_ARITHMETIC_FROM to compile the arithmetic here")
  endif()
endforeach()

# The archives: this tree's instrumented files of libgeomech, and the release tree's objects.
set_property(TARGET geomech PROPERTY SOURCES ${GM_INSTRUMENTED_SOURCES} ${gm_geomech_batches} ${gm_geomech_arithmetic})
set_property(TARGET geomech_reference PROPERTY SOURCES ${gm_reference_objects})
set_property(TARGET geomech_mutants PROPERTY SOURCES ${gm_mutant_batches} ${gm_mutant_alone})
set_property(TARGET geomech_golden PROPERTY SOURCES ${gm_golden_objects})
get_target_property(gm_mutation_sources geomech_mutation SOURCES)
list(TRANSFORM gm_mutation_sources PREPEND ${PROJECT_SOURCE_DIR}/ REGEX "^[^/]")
list(REMOVE_ITEM gm_mutation_sources ${GM_MUTATION_ARITHMETIC_SOURCES})
set_property(TARGET geomech_mutation PROPERTY SOURCES ${gm_mutation_sources} ${gm_mutation_arithmetic})
# Which copy of a template the program runs. An Eigen or Boost.Multiprecision function that the
# arithmetic does not inline is a weak symbol, defined in every object that uses it, and the linker
# keeps the first copy it loads: before, the instrumented -O0 copy of a test's or of the runner's
# object, so the arithmetic compiled at -O1 ran Eigen's accessors at -O0 through ASan (a double
# integrator's negative control took 28.8 s against 0.5 s in the release build). The release
# objects are therefore given to every program's link before its own objects (link options come
# first on CMake's link line), and the archives they come from are linked as ordinary archives
# behind them (a member already loaded is not loaded again): the program runs the arithmetic's
# optimised copies, the instrumented code its own functions instrumented. Measured on that
# control: 28.8 s; 7.7 s with libgeomech's arithmetic first; 2.7 s with the reference's and the
# mutants' first too. A student's program, linked by
# `geomech check` from the archives (toolchain.json), is linked as before.
target_link_options(geomech_whole INTERFACE ${gm_geomech_batches} ${gm_geomech_arithmetic})
set_property(TARGET geomech_whole PROPERTY INTERFACE_LINK_LIBRARIES geomech)
target_link_options(geomech_reference INTERFACE ${gm_reference_objects})
target_link_options(geomech_mutants_whole INTERFACE ${gm_mutant_batches} ${gm_mutant_alone})
set_property(TARGET geomech_mutants_whole PROPERTY INTERFACE_LINK_LIBRARIES geomech_mutants)

# Nothing left here compiles with the uninstrumented precompiled header (the instrumented files of
# libgeomech skip it; the other instrumented targets reuse geomech_fixture's): it is not built.
set_target_properties(geomech geomech_reference geomech_mutants geomech_golden PROPERTIES UNITY_BUILD OFF
                      LINKER_LANGUAGE CXX)
list(LENGTH gm_all_release_objects gm_n_release_objects)
message(STATUS "geomech: the arithmetic, ${gm_n_release_objects} objects, taken from the release build ${GM_FROM}")
