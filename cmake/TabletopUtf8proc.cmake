# utf8proc (Debian's libutf8proc-dev) as one imported target,
# Tabletop::utf8proc: Unicode categories and normalisation for names
# (core/Text.h). Used by the build and, installed beside
# tabletopConfig.cmake, by a project that finds tabletop.
if(TARGET Tabletop::utf8proc)
  return()
endif()
find_path(TABLETOP_UTF8PROC_INCLUDE_DIR utf8proc.h)
find_library(TABLETOP_UTF8PROC_LIBRARY utf8proc)
if(NOT TABLETOP_UTF8PROC_INCLUDE_DIR OR NOT TABLETOP_UTF8PROC_LIBRARY)
  message(FATAL_ERROR "tabletop: utf8proc not found (apt-get install libutf8proc-dev)")
endif()
add_library(Tabletop::utf8proc UNKNOWN IMPORTED)
set_property(TARGET Tabletop::utf8proc PROPERTY IMPORTED_GLOBAL TRUE)
set_target_properties(Tabletop::utf8proc PROPERTIES
  IMPORTED_LOCATION "${TABLETOP_UTF8PROC_LIBRARY}"
  INTERFACE_INCLUDE_DIRECTORIES "${TABLETOP_UTF8PROC_INCLUDE_DIR}")
