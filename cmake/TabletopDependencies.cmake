# Third-party packages, each reached through an imported target.
#
# Bullet, as tabletop::Bullet (its own file: the installed CMake package
# finds it the same way for a consumer).
include(TabletopBullet)

find_package(nlohmann_json 3.10 CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
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
# pybind11 the module is not built (a message says so). A sanitized build
# makes no module: it could not load into a plain interpreter.
option(TABLETOP_PYTHON "Build the Python module (needs pybind11-dev and python3-dev)" ON)
if(TABLETOP_PYTHON AND NOT TABLETOP_SANITIZE)
  if(NOT Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3)
  endif()
  set(PYBIND11_FINDPYTHON ON)
  find_package(Python COMPONENTS Interpreter Development.Module)
  find_package(pybind11 2.10 CONFIG QUIET)
  if(NOT pybind11_FOUND OR NOT Python_FOUND)
    message(STATUS "tabletop: pybind11 or Python's headers not found: no Python module (apt-get install pybind11-dev python3-dev)")
  endif()
endif()
