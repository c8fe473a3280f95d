# Third-party packages, each reached through an imported target.
#
# Bullet, as tabletop::Bullet (its own file: the installed CMake package
# finds it the same way for a consumer).
include(TabletopBullet)

find_package(nlohmann_json 3.10 CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)

# Rendering: libpng for images; OpenGL headers, freeglut and X11 for the
# window; OSMesa (pkg-config) for headless frames (see src/headless).
find_package(PNG REQUIRED)
find_package(OpenGL REQUIRED)
find_package(GLUT REQUIRED)
find_package(X11 REQUIRED)
