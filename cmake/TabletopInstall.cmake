# What `cmake --install` puts under a prefix, in the usual layout:
#   bin/                  tabletop and the four example programs,
#                         tabletop-example1_single_cube ...
#   lib/                  the libraries (static)
#   include/tabletop/     their headers, by layer (core/, physics/, sim/ ...),
#                         included as <tabletop/sim/SceneBuilder.h> with
#                         only include/ on the path
#   share/tabletop/       the shipped scenarios, the tolerance front and
#                         the JSON Schemas of scenarios and run --json,
#                         found by the installed programs (app/DataPaths.h)
#   lib/cmake/tabletop/   the CMake package: find_package(tabletop) gives
#                         tabletop::core, tabletop::physics, tabletop::sim ...
#                         with Bullet found for the consumer as the build
#                         found it (float or double).
include(CMakePackageConfigHelpers)

# Every library but the command line's own, named without the prefix.
set(TABLETOP_EXPORTED
  options core io rules physics compat scenario sim scenes measure sweep
  draw image render headless session viewer)
foreach(_name IN LISTS TABLETOP_EXPORTED)
  set_target_properties(tabletop_${_name} PROPERTIES EXPORT_NAME ${_name})
  list(APPEND _tabletop_targets tabletop_${_name})
endforeach()

# Their include folder, PREFIX/include, comes with tabletop::core (every
# library links it) and tabletop::io.
install(TARGETS ${_tabletop_targets} EXPORT tabletopTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})

# The libraries' headers, by layer, their includes of each other written
# <tabletop/layer/Name.h> (cmake/TabletopInstallHeaders.cmake). The command
# line's (app/) and the Python module's are not a library's.
set(TABLETOP_HEADER_LAYERS
  core io rules physics compat scenario sim scenes measure sweep draw image render headless viewer)
install(CODE "
  set(TABLETOP_SOURCE_DIR \"${PROJECT_SOURCE_DIR}\")
  set(TABLETOP_STAGING_DIR \"${PROJECT_BINARY_DIR}/installed-headers\")
  set(TABLETOP_INCLUDE_DIR \"${CMAKE_INSTALL_INCLUDEDIR}\")
  set(TABLETOP_HEADER_LAYERS \"${TABLETOP_HEADER_LAYERS}\")
  include(\"${PROJECT_SOURCE_DIR}/cmake/TabletopInstallHeaders.cmake\")")

install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenarios/ DESTINATION ${CMAKE_INSTALL_DATADIR}/tabletop/scenarios)
install(FILES ${PROJECT_SOURCE_DIR}/data/tolerance_front.json DESTINATION ${CMAKE_INSTALL_DATADIR}/tabletop/data)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/schema DESTINATION ${CMAKE_INSTALL_DATADIR}/tabletop/data)

set(TABLETOP_PACKAGE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/tabletop)
install(EXPORT tabletopTargets NAMESPACE tabletop:: DESTINATION ${TABLETOP_PACKAGE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/tabletopConfig.cmake.in
  ${PROJECT_BINARY_DIR}/tabletopConfig.cmake INSTALL_DESTINATION ${TABLETOP_PACKAGE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/tabletopConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/tabletopConfig.cmake ${PROJECT_BINARY_DIR}/tabletopConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/TabletopBullet.cmake ${PROJECT_SOURCE_DIR}/cmake/TabletopUtf8proc.cmake DESTINATION ${TABLETOP_PACKAGE_DIR})
