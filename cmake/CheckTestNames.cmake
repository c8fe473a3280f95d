# Checks the names of the test suite (tests/CMakeLists.txt registers it as
# Suite.NamesAreReadableUniqueAndStable):
#   cmake -DCTEST_COMMAND=ctest -DBINARY_DIR=build -P CheckTestNames.cmake [GTEST_EXECUTABLE ...]
# Every CTest name holds letters, digits and '_', '.', '/' only (so no
# "72-byte object <CA-F7 ...>" dump of a parameter, which changes from build
# to build), no two are equal, and no value-parameterised case is known by
# its index alone (".../3": its INSTANTIATE_TEST_SUITE_P lacks a name
# generator, tests/support/TestName.h). Each GoogleTest executable lists
# its tests twice, in two processes, and the two lists must be the same.

cmake_minimum_required(VERSION 3.20)

# The names CTest knows, from `ctest -N`.
execute_process(COMMAND ${CTEST_COMMAND} -N --test-dir ${BINARY_DIR}
  OUTPUT_VARIABLE listing RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "ctest -N --test-dir ${BINARY_DIR} failed (${status})")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(names "")
set(bad "")
foreach(line IN LISTS lines)
  if(NOT line MATCHES "^ *Test +#[0-9]+: (.*)$")
    continue()
  endif()
  set(name "${CMAKE_MATCH_1}")
  if(name MATCHES "byte object" OR NOT name MATCHES "^[A-Za-z0-9_./]+$")
    string(APPEND bad "\n  not letters, digits, '_', '.', '/': ${name}")
  elseif(name MATCHES "/[0-9]+$")
    string(APPEND bad "\n  named by its index, not its parameters: ${name}")
  endif()
  if(name IN_LIST names)
    string(APPEND bad "\n  registered twice: ${name}")
  endif()
  list(APPEND names "${name}")
endforeach()
list(LENGTH names count)
if(count EQUAL 0)
  message(FATAL_ERROR "ctest -N listed no tests in ${BINARY_DIR}")
endif()

# Two listings of each executable, names only (the "# GetParam() = ..."
# comments are the printed values, which the names do not use).
set(executables "")
set(script_seen FALSE)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(index RANGE 1 ${last})
  if(script_seen)
    list(APPEND executables "${CMAKE_ARGV${index}}")
  elseif(CMAKE_ARGV${index} STREQUAL "-P")
    math(EXPR index_of_script "${index} + 1")
  elseif(DEFINED index_of_script AND index EQUAL index_of_script)
    set(script_seen TRUE)
  endif()
endforeach()
foreach(executable IN LISTS executables)
  set(previous "")
  foreach(run 1 2)
    execute_process(COMMAND ${executable} --gtest_list_tests OUTPUT_VARIABLE tests RESULT_VARIABLE status)
    if(NOT status EQUAL 0)
      string(APPEND bad "\n  ${executable} --gtest_list_tests failed (${status})")
      break()
    endif()
    string(REGEX REPLACE " +#[^\n]*" "" tests "${tests}")
    if(run EQUAL 2 AND NOT tests STREQUAL previous)
      string(APPEND bad "\n  ${executable}: its tests' names differ between two listings")
    endif()
    set(previous "${tests}")
  endforeach()
endforeach()

if(bad)
  message(FATAL_ERROR "test names that cannot be run again by name:${bad}")
endif()
message(STATUS "${count} test names: letters, digits, '_', '.', '/', each once, the same in two listings")
