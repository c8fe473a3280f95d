# Bullet as one imported target, Tabletop::Bullet: used by the build and,
# installed beside tabletopConfig.cmake, by a project that finds tabletop.
#
# Debian's BulletConfig.cmake only sets variables (BULLET_INCLUDE_DIR is
# relative to BULLET_ROOT_DIR), so it is wrapped here into Tabletop::Bullet.
# Debian ships a float build (BulletConfig.cmake) and a double build
# (BulletConfig-float64.cmake); TABLETOP_DOUBLE_PRECISION picks one.

if(TABLETOP_DOUBLE_PRECISION)
  set(_tabletop_bullet_config BulletConfig-float64.cmake)
else()
  set(_tabletop_bullet_config BulletConfig.cmake)
endif()
if(TARGET Tabletop::Bullet)
  return()
endif()
find_package(Bullet CONFIG REQUIRED CONFIGS ${_tabletop_bullet_config})

add_library(Tabletop::Bullet INTERFACE IMPORTED)
set_property(TARGET Tabletop::Bullet PROPERTY IMPORTED_GLOBAL TRUE)
set(_tabletop_bullet_include "${BULLET_ROOT_DIR}/${BULLET_INCLUDE_DIR}")
if(IS_ABSOLUTE "${BULLET_INCLUDE_DIR}")
  set(_tabletop_bullet_include "${BULLET_INCLUDE_DIR}")
endif()
set_target_properties(Tabletop::Bullet PROPERTIES
  INTERFACE_INCLUDE_DIRECTORIES "${_tabletop_bullet_include}")
string(REPLACE "-D" "" _tabletop_bullet_defs "${BULLET_DEFINITIONS}")
if(_tabletop_bullet_defs)
  set_property(TARGET Tabletop::Bullet PROPERTY
    INTERFACE_COMPILE_DEFINITIONS ${_tabletop_bullet_defs})
endif()

# Only the three libraries the rigid-body pipeline needs, in link order.
# The double build names them with a suffix ("LinearMath-float64").
set(_tabletop_bullet_suffix "")
foreach(_name IN LISTS BULLET_LIBRARIES)
  if(_name MATCHES "^LinearMath(.*)$")
    set(_tabletop_bullet_suffix "${CMAKE_MATCH_1}")
  endif()
endforeach()
set(_tabletop_bullet_libs)
foreach(_name BulletDynamics BulletCollision LinearMath)
  find_library(TABLETOP_${_name}_LIBRARY NAMES ${_name}${_tabletop_bullet_suffix}
    HINTS "${BULLET_ROOT_DIR}/${BULLET_LIBRARY_DIRS}" REQUIRED NO_CACHE)
  list(APPEND _tabletop_bullet_libs ${TABLETOP_${_name}_LIBRARY})
endforeach()
set_property(TARGET Tabletop::Bullet PROPERTY
  INTERFACE_LINK_LIBRARIES ${_tabletop_bullet_libs})
if(NOT tabletop_FIND_QUIETLY)
  message(STATUS "tabletop: Bullet ${BULLET_VERSION_STRING} from ${_tabletop_bullet_config}")
endif()
