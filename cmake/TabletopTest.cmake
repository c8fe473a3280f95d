# tabletop_test(NAME SOURCES ... [LIBS ...] [LABELS ...]): one GoogleTest
# executable whose cases CTest discovers one by one.
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
endfunction()
