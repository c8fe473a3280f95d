# Third-party packages, each reached through an imported target.
#
# Bullet, as tabletop::Bullet (its own file: the installed CMake package
# finds it the same way for a consumer).
include(TabletopBullet)

find_package(nlohmann_json 3.10 CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
# Threads: the step solves independent islands on every core.
find_package(Threads REQUIRED)
# utf8proc, as Tabletop::utf8proc (its own file, like Bullet's).
include(TabletopUtf8proc)

# Rendering: libpng for images; OpenGL headers, freeglut and X11 for the
# window; OSMesa (pkg-config) for headless frames (see src/headless).
find_package(PNG REQUIRED)
find_package(OpenGL REQUIRED)
find_package(GLUT REQUIRED)
find_package(X11 REQUIRED)

# Python (src/python): Debian's interpreter, the one its python3-numpy and
# python3-pytest serve, found first; pybind11 from pybind11-dev. Without
# pybind11 the module is not built (a message says so). A sanitized module
# cannot load into a plain interpreter unless the AddressSanitizer runtime
# is loaded first: its tests preload GCC's shared runtime, and libstdc++
# with it (python3 does not link it, and the runtime looks for C++'s
# __cxa_throw when it starts: without it the first exception thrown aborts).
# TABLETOP_PYTHON_PRELOAD lists both. Where there is no shared runtime
# (clang links its own into executables only, the fuzzer's build) no
# module is built.
option(TABLETOP_PYTHON "Build the Python module (needs pybind11-dev and python3-dev)" ON)
set(TABLETOP_BUILD_PYTHON OFF)
if(TABLETOP_PYTHON)
  if(NOT Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3)
  endif()
  set(PYBIND11_FINDPYTHON ON)
  find_package(Python COMPONENTS Interpreter Development.Module)
  find_package(pybind11 2.10 CONFIG QUIET)
  if(NOT pybind11_FOUND OR NOT Python_FOUND)
    message(STATUS "tabletop: pybind11 or Python's headers not found: no Python module (apt-get install pybind11-dev python3-dev)")
  elseif(TABLETOP_SANITIZE)
    execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libasan.so
      OUTPUT_VARIABLE _asan OUTPUT_STRIP_TRAILING_WHITESPACE)
    execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libstdc++.so
      OUTPUT_VARIABLE _stdcxx OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND IS_ABSOLUTE "${_asan}" AND EXISTS "${_asan}"
       AND IS_ABSOLUTE "${_stdcxx}" AND EXISTS "${_stdcxx}")
      set(TABLETOP_PYTHON_PRELOAD "${_asan}:${_stdcxx}")
      set(TABLETOP_BUILD_PYTHON ON)
    else()
      message(STATUS "tabletop: no shared AddressSanitizer runtime to preload: no sanitized Python module")
    endif()
  else()
    set(TABLETOP_BUILD_PYTHON ON)
  endif()
endif()
