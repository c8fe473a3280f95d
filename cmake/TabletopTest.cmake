# tabletop_test(NAME SOURCES ... [LIBS ...] [LABELS ...]): one GoogleTest
# executable whose cases CTest discovers one by one; then
# tabletop_check_test_names(): a test of all their names.
find_package(GTest REQUIRED)
include(GoogleTest)

# Where the tests write their files (tests/support/TempFiles.h): under the
# build tree, not the machine's /tmp.
set(TABLETOP_TEST_TMPDIR "${PROJECT_BINARY_DIR}/test-tmp/")
file(MAKE_DIRECTORY "${TABLETOP_TEST_TMPDIR}")

function(tabletop_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest_main Tabletop::options)
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
  target_compile_definitions(${name} PRIVATE
    TABLETOP_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    TABLETOP_BINARY_DIR="${PROJECT_BINARY_DIR}"
    TABLETOP_TEST_TMPDIR="${TABLETOP_TEST_TMPDIR}")
  set(_labels unit)
  if(ARG_LABELS)
    set(_labels ${ARG_LABELS})
  endif()
  # Mesa's on-disk shader cache is off in tests, so a test leaves nothing
  # in the user's home; llvmpipe draws on the calling thread, so no worker
  # threads are left winding down at exit. (The LeakSanitizer tracer
  # crashes once put down to these were the runtime's __tls_get_addr bug:
  # cmake/SanitizerDefaults.cpp.)
  # NO_PRETTY_VALUES: a value-parameterised case is named by its suite's
  # name generator (tests/support/TestName.h), never by its printed value,
  # which for a struct is a dump of its bytes (pointers and padding
  # included) and which CMake 3.25 also appends to a generated name.
  gtest_discover_tests(${name}
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    NO_PRETTY_VALUES
    PROPERTIES LABELS "${_labels}" ENVIRONMENT "MESA_SHADER_CACHE_DISABLE=true"
    ENVIRONMENT_MODIFICATION "LP_NUM_THREADS=set:0"
    DISCOVERY_TIMEOUT 60)
  # For the check of the suite's names (tabletop_check_test_names).
  set_property(DIRECTORY APPEND PROPERTY TABLETOP_GTEST_EXECUTABLES $<TARGET_FILE:${name}>)
endfunction()

# Suite.NamesAreReadableUniqueAndStable: every CTest name in the build can
# be fed back to `ctest -R`, and each executable of tabletop_test names
# its tests the same way twice (cmake/CheckTestNames.cmake). Called once,
# after the last tabletop_test of the directory.
function(tabletop_check_test_names)
  get_property(executables DIRECTORY PROPERTY TABLETOP_GTEST_EXECUTABLES)
  add_test(NAME Suite.NamesAreReadableUniqueAndStable
    COMMAND ${CMAKE_COMMAND} -DCTEST_COMMAND=${CMAKE_CTEST_COMMAND} -DBINARY_DIR=${PROJECT_BINARY_DIR}
      -P ${PROJECT_SOURCE_DIR}/cmake/CheckTestNames.cmake ${executables})
  set_tests_properties(Suite.NamesAreReadableUniqueAndStable PROPERTIES LABELS unit TIMEOUT 300
    ENVIRONMENT "MESA_SHADER_CACHE_DISABLE=true")
endfunction()

# tabletop_pytest(NAME FILE file [MARKS expr] LABELS ...): the tests of one
# file of tests/python (those pytest's -m EXPR selects) as one CTest entry,
# so that `ctest -j` runs the files side by side and a failure names its
# file; pytest's summary names the test. CTest's environment: the built
# module and command line (tests/python/conftest.py fails without them).
function(tabletop_pytest name)
  cmake_parse_arguments(ARG "" "FILE;MARKS" "LABELS" ${ARGN})
  set_property(DIRECTORY APPEND PROPERTY TABLETOP_PYTEST_FILES ${ARG_FILE})
  set(env "PYTHONPATH=${PROJECT_BINARY_DIR}/python;TABLETOP_BIN=$<TARGET_FILE:tabletop>;TABLETOP_SOURCE_DIR=${PROJECT_SOURCE_DIR};MESA_SHADER_CACHE_DISABLE=true")
  if(TABLETOP_SANITIZE)
    # The sanitized module's memory is what this build checks: the physics
    # and docs checks marked slow or docs run in the plain build alone.
    if("slow" IN_LIST ARG_LABELS OR "docs" IN_LIST ARG_LABELS)
      return()
    endif()
    # The runtime preloaded (cmake/TabletopDependencies.cmake says why),
    # without leak checking: Python keeps much of what it allocates until
    # exit by design.
    list(APPEND env "LD_PRELOAD=${TABLETOP_PYTHON_PRELOAD}"
      "ASAN_OPTIONS=detect_leaks=0:halt_on_error=1:abort_on_error=0:intercept_tls_get_addr=0"
      "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
  endif()
  set(select "")
  if(ARG_MARKS)
    set(select -m "${ARG_MARKS}")
  endif()
  add_test(NAME ${name}
    COMMAND ${Python_EXECUTABLE} -m pytest -q -p no:cacheprovider ${select} ${PROJECT_SOURCE_DIR}/tests/python/${ARG_FILE})
  set_tests_properties(${name} PROPERTIES LABELS "${ARG_LABELS}" TIMEOUT 900 ENVIRONMENT "${env}")
endfunction()

# Python.EveryTestFileHasAnEntry: pytest collects nothing in tests/python
# once the files of tabletop_pytest are left out, so that no test file is
# left out of the suite unseen; its output lists what was. Called once,
# after the last tabletop_pytest.
function(tabletop_check_pytest_files)
  get_property(files DIRECTORY PROPERTY TABLETOP_PYTEST_FILES)
  list(REMOVE_DUPLICATES files)
  set(ignored "")
  foreach(file IN LISTS files)
    list(APPEND ignored --ignore=${PROJECT_SOURCE_DIR}/tests/python/${file})
  endforeach()
  add_test(NAME Python.EveryTestFileHasAnEntry
    COMMAND ${Python_EXECUTABLE} -m pytest --collect-only -q -p no:cacheprovider ${ignored} ${PROJECT_SOURCE_DIR}/tests/python)
  set_tests_properties(Python.EveryTestFileHasAnEntry PROPERTIES LABELS python TIMEOUT 120
    PASS_REGULAR_EXPRESSION "no tests collected in"
    ENVIRONMENT "PYTHONPATH=${PROJECT_BINARY_DIR}/python;TABLETOP_BIN=$<TARGET_FILE:tabletop>;TABLETOP_SOURCE_DIR=${PROJECT_SOURCE_DIR}$<$<BOOL:${TABLETOP_SANITIZE}>:;LD_PRELOAD=${TABLETOP_PYTHON_PRELOAD};ASAN_OPTIONS=detect_leaks=0:intercept_tls_get_addr=0>")
endfunction()
