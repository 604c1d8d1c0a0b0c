# How every GoogleTest executable is registered with ctest: one precompiled header shared by all
# test programs, labels read from the source, and a timeout on every test.
#
# Labels (ctest -L / -LE):
#   shared  the source reads ../shared (FIELDLINES_REQUIRE_SHARED): fails under CI without it
#   window  a real studio window under Xvfb (registered by tests/studio with RESOURCE_LOCK)
#   slow    the source says so on a line `// ctest-label: slow` (tests over ~30 s); they start
#           first
# Timeouts: FIELDLINES_TEST_TIMEOUT seconds per test (a sanitized build runs ~3x slower, so the
# asan preset raises it), so one hang ends its test instead of the CI budget.
set(FIELDLINES_TEST_TIMEOUT 240 CACHE STRING "ctest timeout per test, seconds")
# Test code is compiled at -O0 whatever the build type: the libraries it calls keep their
# optimisation, and gtest's macro-heavy files take half the time of -O1 (20 s against 10 s for
# training_cli_test.cpp under the sanitizers) while their own loops are a small part of a run.
set(FIELDLINES_TEST_COMPILE_OPTIONS -O0)

# The heavy headers nearly every test includes. Tests keep their own includes: the PCH only
# makes them cheap, so a test still builds with FIELDLINES_PCH=OFF (cmake/precompiled_headers.cmake).
if(FIELDLINES_PCH AND NOT TARGET fieldlines_test_pch)
  file(WRITE ${CMAKE_BINARY_DIR}/fieldlines_test_pch.cpp "// host of the shared test PCH\n")
  add_library(fieldlines_test_pch OBJECT ${CMAKE_BINARY_DIR}/fieldlines_test_pch.cpp)
  target_link_libraries(fieldlines_test_pch PRIVATE fieldlines::core fieldlines_warnings GTest::gtest)
  target_compile_options(fieldlines_test_pch PRIVATE ${FIELDLINES_TEST_COMPILE_OPTIONS})
  target_precompile_headers(fieldlines_test_pch PRIVATE
    <gtest/gtest.h> <opencv2/core.hpp> <opencv2/imgproc.hpp> <nlohmann/json.hpp>
    <filesystem> <fstream> <functional> <map> <memory> <optional> <sstream> <string> <vector>)
endif()

# fieldlines_test_code(<target>): compiled as test code (the options above, the shared PCH).
function(fieldlines_test_code target)
  target_compile_options(${target} PRIVATE ${FIELDLINES_TEST_COMPILE_OPTIONS})
  if(TARGET fieldlines_test_pch)
    target_precompile_headers(${target} REUSE_FROM fieldlines_test_pch)
  endif()
endfunction()

# fieldlines_test_labels(<source> <out-var>): the labels the source declares or implies.
function(fieldlines_test_labels source out)
  set(labels "")
  file(STRINGS ${source} uses_shared REGEX "FIELDLINES_REQUIRE_SHARED\\(")
  if(uses_shared)
    list(APPEND labels shared)
  endif()
  file(STRINGS ${source} declared REGEX "^// ctest-label: ")
  foreach(line ${declared})
    string(REGEX REPLACE "^// ctest-label: *" "" label "${line}")
    list(APPEND labels ${label})
  endforeach()
  set(${out} ${labels} PARENT_SCOPE)
endfunction()

# fieldlines_label_discovered_tests(<target> <labels>): gtest_discover_tests flattens a list
# value among its PROPERTIES (two labels become a label and a stray property), so the labels are
# set by a ctest include file of this folder, read after every discovered test of it is known
# (gtest_discover_tests names them in <target>_TESTS).
function(fieldlines_label_discovered_tests target labels)
  if(NOT labels)
    return()
  endif()
  set(file ${CMAKE_CURRENT_BINARY_DIR}/fieldlines_test_labels.cmake)
  get_property(started DIRECTORY PROPERTY FIELDLINES_TEST_LABELS_FILE SET)
  if(NOT started)
    file(WRITE ${file} "# Labels of the discovered tests (cmake/test_helpers.cmake)\n")
    set_property(DIRECTORY PROPERTY FIELDLINES_TEST_LABELS_FILE ${file})
    # Deferred to the end of the folder's CMakeLists, so it is read after every discovery file
    # (EVAL: a deferred call's arguments are expanded when it runs, outside this function).
    cmake_language(EVAL CODE
      "cmake_language(DEFER CALL set_property DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES [[${file}]])")
  endif()
  file(APPEND ${file} "if(${target}_TESTS)\n  set_tests_properties(\${${target}_TESTS} PROPERTIES LABELS \"${labels}\")\nendif()\n")
endfunction()

# fieldlines_add_gtest(<target> <source> [LABELS ...] [PROPERTIES ...]): registers the
# program's tests with the labels, the timeout and any extra test properties.
function(fieldlines_add_gtest target source)
  cmake_parse_arguments(arg "" "PREFIX" "LABELS;PROPERTIES" ${ARGN})
  fieldlines_test_code(${target})
  fieldlines_test_labels(${source} labels)
  list(APPEND labels ${arg_LABELS})
  # A clean build has no timings yet: start the slow programs first so they do not end the run.
  set(cost_property "")
  if(slow IN_LIST labels)
    set(cost_property COST 100)
  endif()
  set(prefix_args "")
  if(arg_PREFIX)
    set(prefix_args TEST_PREFIX ${arg_PREFIX})
  endif()
  gtest_discover_tests(${target} ${prefix_args} DISCOVERY_TIMEOUT 60
                       PROPERTIES TIMEOUT ${FIELDLINES_TEST_TIMEOUT} ${cost_property} ${arg_PROPERTIES})
  fieldlines_label_discovered_tests(${target} "${labels}")
endfunction()
