# Run by `cmake --install` (see TabletopInstall.cmake): installs the
# libraries' headers under PREFIX/include/tabletop/<layer>/, each include of
# a tabletop header written as a consumer writes it:
#   #include "core/Arrow.h"   ->   #include <tabletop/core/Arrow.h>
# The sources include each other by layer with src/ on their path; the
# installed headers then need only PREFIX/include, and tabletop's core/,
# sim/, io/ ... cannot clash with another library's folders.
# Needs TABLETOP_SOURCE_DIR, TABLETOP_STAGING_DIR, TABLETOP_INCLUDE_DIR
# (relative to the prefix) and TABLETOP_HEADER_LAYERS.
list(JOIN TABLETOP_HEADER_LAYERS "|" _layers)
set(_staged "")
foreach(_layer IN LISTS TABLETOP_HEADER_LAYERS)
  file(GLOB_RECURSE _headers RELATIVE ${TABLETOP_SOURCE_DIR}/src ${TABLETOP_SOURCE_DIR}/src/${_layer}/*.h)
  foreach(_header IN LISTS _headers)
    file(READ ${TABLETOP_SOURCE_DIR}/src/${_header} _text)
    string(REGEX REPLACE "#include \"((${_layers})/[^\"]+)\"" "#include <tabletop/\\1>" _text "${_text}")
    # Written only when changed, so an install over an install is quiet.
    set(_out ${TABLETOP_STAGING_DIR}/tabletop/${_header})
    set(_old "")
    if(EXISTS ${_out})
      file(READ ${_out} _old)
    endif()
    if(NOT _old STREQUAL _text)
      file(WRITE ${_out} "${_text}")
    endif()
    list(APPEND _staged ${_out})
  endforeach()
endforeach()
# A header gone from the sources goes from the staging folder too.
file(GLOB_RECURSE _present ${TABLETOP_STAGING_DIR}/tabletop/*)
foreach(_file IN LISTS _present)
  list(FIND _staged ${_file} _at)  # (no IN_LIST: cmake_install.cmake sets no policies)
  if(_at EQUAL -1)
    file(REMOVE ${_file})
  endif()
endforeach()
file(INSTALL ${TABLETOP_STAGING_DIR}/tabletop DESTINATION ${CMAKE_INSTALL_PREFIX}/${TABLETOP_INCLUDE_DIR})
